package diffract.optics.rigorous;

/**
 * How finely the Fourier modal method resolves a grating: the harmonics kept and the staircase's layers.
 *
 * <p>Harmonics: M = 0 chooses per wavelength, M = ceil(2 period / lambda) + {@link #AUTO_MARGIN}: every order that can
 * propagate from any direction (|m| lambda / period &lt;= 2) and a margin of evanescent ones, which carry the near
 * field of the relief (on the sinusoids and ridges of the validity map this holds the efficiencies of the orders that
 * matter to 0.2 %; {@link Convergence} reports it per case).
 *
 * <p>Layers: the staircase of L slabs converges as about L^-1.5 on smooth profiles (the flat crests and troughs are
 * sliced coarsely; L^-2 where the slopes are straight), so the efficiencies are extrapolated from L / 2 and L slabs,
 * eta = eta_L + (eta_L - eta_{L/2}) / (2^{1.5} - 1), unless {@code extrapolate} is off. The extrapolation leaves
 * between 5 % (order 1.6) and 20 % (order 2) of the last step's change.
 *
 * @param maxOrder    M, the highest harmonic kept (2M + 1 in all), or 0 for the automatic choice
 * @param layers      L, the staircase's slabs (even when extrapolating)
 * @param extrapolate whether to extrapolate from L / 2 and L slabs
 */
public record Resolution(int maxOrder, int layers, boolean extrapolate) {
    /** Evanescent harmonics kept beyond those that can propagate. */
    public static final int AUTO_MARGIN = 12;
    /** The default: harmonics chosen per wavelength, 24 layers extrapolated from 12. */
    public static final Resolution DEFAULT = new Resolution(0, 24, true);
    /** The largest M the command line accepts (4001 harmonics: a 2-D cell's memory is checked separately). */
    public static final int MAX_ORDER = 2000;
    /** The largest L the command line accepts. */
    public static final int MAX_LAYERS = 1000;
    /** The order of the staircase's convergence assumed by the extrapolation. */
    static final double STAIRCASE_ORDER = 1.5;

    public Resolution {
        if (maxOrder < 0 || maxOrder > MAX_ORDER) {
            throw new IllegalArgumentException("the highest harmonic must be in [0, " + MAX_ORDER + "] (0: automatic), got "
                    + maxOrder);
        }
        if (layers < 1 || layers > MAX_LAYERS) {
            throw new IllegalArgumentException("the staircase's layers must be in [1, " + MAX_LAYERS + "], got " + layers);
        }
        if (extrapolate && (layers < 2 || layers % 2 != 0)) {
            throw new IllegalArgumentException("extrapolating the staircase needs an even number of layers >= 2, got "
                    + layers);
        }
    }

    /** M for light of {@code lambdaUm} on a period of {@code periodUm}. */
    public int maxOrder(double periodUm, double lambdaUm) {
        return maxOrder > 0 ? maxOrder : (int) Math.ceil(2 * periodUm / lambdaUm) + AUTO_MARGIN;
    }

    public Resolution withMaxOrder(int m) {
        return new Resolution(m, layers, extrapolate);
    }

    public Resolution withLayers(int l) {
        return new Resolution(maxOrder, l, extrapolate && l % 2 == 0 && l >= 2);
    }

    /** "M auto, 24 layers extrapolated from 12" or "M 20, 40 layers". */
    public String describe() {
        return (maxOrder == 0 ? "harmonics up to 2 period / lambda + " + AUTO_MARGIN : "harmonics up to " + maxOrder)
                + ", " + layers + " layers" + (extrapolate ? " extrapolated from " + layers / 2 : "");
    }
}
