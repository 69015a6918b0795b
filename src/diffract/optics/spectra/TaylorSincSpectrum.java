package diffract.optics.spectra;

import diffract.optics.windows.CoherenceWindow;
import diffract.optics.windows.WindowPlacement;
import diffract.optics.windows.WindowRadii;

/**
 * The PQ approach (004 sections "PQ factors" and "Sinc Interpolation"; 003 section 1.5.3): the surface is taken
 * as R_x x R_y replicas of the patch, so its transform is the patch's transform times the geometric series
 * (p + i q) = sum_{n=0}^{R-1} e^{-i omega n T} per axis (eq. {@code pqgeometricseries}), and the patch's own
 * transform between DFT texels is reconstructed by sinc interpolation instead of the Gaussian window.
 *
 * <p>|p + i q| for one axis is the Dirichlet kernel |sin(R pi s) / sin(pi s)| with omega T = 2 pi s, s the
 * lookup of eq. 1.8. In 2-D the factor is the complex product (p1 + i q1)(p2 + i q2) = (p1 p2 - q1 q2) +
 * i (p1 q2 + q1 p2), whose modulus is |p1 + i q1| |p2 + i q2| (the thesis' eq. {@code pqsubst2} writes
 * q = p1 p2 + q1 q2, a slip). We divide by R per axis so that a flat mirror stays exactly 1 (the relative
 * BRDF); the default R spans the coherence length 65 um, the same physics the Gaussian window models.
 * At integer s the kernel's 0/0 is replaced by its limit cos(R pi s) / cos(pi s), never divided.
 *
 * <p>sinc(s - m) D_R(s) = +-sinc(R (s - m)): the R replicas under the sinc are one box window R L wide. Averaged over
 * the box's position ({@link WindowPlacement#AVERAGED}) every pair of texels drops out as for the Gaussian window, and
 * |P|^2 = D_R(s)^2 sum_m sinc(s - m)^2 |T_m|^2 = sum_m sinc(R (s - m))^2 |T_m|^2 over the window's texels.
 */
public final class TaylorSincSpectrum extends WindowedTaylorSpectrum {
    private final int replicasX;
    private final int replicasY;

    public TaylorSincSpectrum(TaylorTerms terms, int highestOrder, int windowRadius, int replicasX, int replicasY,
                              WindowPlacement placement) {
        this(terms, highestOrder, new WindowRadii(windowRadius, windowRadius), 0.0, replicasX, replicasY, placement);
    }

    /** With per-axis window radii and the early-stop tolerance of {@link TaylorBound#stopOrder} (0 = fixed N). */
    public TaylorSincSpectrum(TaylorTerms terms, int highestOrder, WindowRadii radii, double taylorTolerance,
                              int replicasX, int replicasY, WindowPlacement placement) {
        super(new WindowedTaylorSum(terms, highestOrder, radii, taylorTolerance, TaylorSincSpectrum::sinc,
                TaylorSincSpectrum::sinc, placement));
        if (replicasX < 1 || replicasY < 1) {
            throw new IllegalArgumentException("need replicas >= 1");
        }
        this.replicasX = replicasX;
        this.replicasY = replicasY;
    }

    /** Replicas that span the coherence length 4 sigma_s along an axis of the given extent, at least 1. */
    public static int replicasForCoherence(CoherenceWindow window, double extentUm) {
        return Math.max(1, (int) Math.round(4.0 * window.sigmaSpatialUm() / extentUm));
    }

    @Override
    double replicationFactor(double sx, double sy) {
        double px = normalisedDirichlet(sx, replicasX);
        double py = normalisedDirichlet(sy, replicasY);
        return px * px * py * py;
    }

    /** sin(pi x) / (pi x), 1 at 0. */
    static double sinc(double x) {
        if (Math.abs(x) < 1e-8) {
            return 1.0;
        }
        double px = Math.PI * x;
        return Math.sin(px) / px;
    }

    /**
     * sin(R pi s) / (R sin(pi s)): the modulus of the geometric series over R replicas divided by R, with its
     * sign. With s = m + f, the sines give (-1)^((R-1) m) sin(R pi f) / (R sin(pi f)); where both vanish
     * (|pi f| < 1e-6) the series 1 - (R^2 - 1)(pi f)^2 / 6 replaces the 0/0 (next term O((R pi f)^4) < 1e-16 R^4).
     */
    public static double normalisedDirichlet(double s, int replicas) {
        if (replicas == 1) {
            return 1.0;
        }
        long m = (long) Math.rint(s);
        double sign = (m * (replicas - 1)) % 2 == 0 ? 1.0 : -1.0;
        double pf = Math.PI * (s - m);
        if (Math.abs(pf) < 1e-6) {
            return sign * (1.0 - (replicas * (double) replicas - 1.0) * pf * pf / 6.0);
        }
        return sign * Math.sin(replicas * pf) / (replicas * Math.sin(pf));
    }
}
