package diffract.optics.rigorous;

import diffract.optics.settings.OrderWeights;
import diffract.optics.settings.Polarisation;


/**
 * The settings of Maxwell's equations: how finely the Fourier modal method resolves the patch ({@link Resolution}:
 * the harmonics kept, the staircase's layers and its extrapolation), the light's polarisation, and whether the lobes
 * method takes its orders from them ({@link OrderWeights}). The material's complex index is the illumination's
 * ({@code IlluminationSettings.material}); the rigorous method's wavelength nodes are the
 * spectral settings' step. Other methods ignore these.
 *
 * @param resolution   harmonics and layers
 * @param polarisation the incident light's polarisation
 * @param orders       the lobes method's orders: the scalar model's, or from the rigorous solves
 */
public record RigorousSettings(Resolution resolution, Polarisation polarisation, OrderWeights orders) {
    /** Harmonics chosen per wavelength, 24 layers extrapolated from 12, unpolarised light, the scalar orders. */
    public static final RigorousSettings DEFAULT = new RigorousSettings(Resolution.DEFAULT, Polarisation.UNPOLARISED,
            OrderWeights.SCALAR);

    public RigorousSettings {
        if (resolution == null || polarisation == null || orders == null) {
            throw new NullPointerException("the resolution, the polarisation and the orders are required");
        }
    }

    public RigorousSettings withResolution(Resolution r) {
        return new RigorousSettings(r, polarisation, orders);
    }

    public RigorousSettings withPolarisation(Polarisation p) {
        return new RigorousSettings(resolution, p, orders);
    }

    public RigorousSettings withOrders(OrderWeights o) {
        return new RigorousSettings(resolution, polarisation, o);
    }
}
