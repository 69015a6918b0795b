package diffract.optics.windows;

/**
 * The half-widths of the coherence window's texel neighbourhood per axis: the window covers the
 * (2 x + 1) x (2 y + 1) texels around the nearest texel round(s) (003 eq. 1.9, anchored as in
 * {@code TaylorGaussianSpectrum}). The thesis fixed 3 x 3 (x = y = 1) whatever sigma_f; {@link
 * #automatic} follows sigma_f = L / (2 pi sigma_s) texels ({@link CoherenceWindow#sigmaTexels}) instead.
 */
public record WindowRadii(int x, int y) {
    /**
     * The share of the window's weight the automatic radius captures at least: 99.73 %, a continuous Gaussian's
     * mass within 3 sigma ("ceil(3 sigma)", made exact for the discrete window).
     */
    public static final double AUTOMATIC_CAPTURE = 0.9973;
    /** Cap of the automatic radius: a 17 x 17 window (289 texels x N terms per wavelength) is already costly. */
    public static final int MAX_AUTOMATIC = 8;

    public WindowRadii {
        if (x < 0 || y < 0) {
            throw new IllegalArgumentException("window radii must be >= 0, got " + x + ", " + y);
        }
    }

    /**
     * The smallest radius R whose window captures {@link #AUTOMATIC_CAPTURE} of the window's weight per axis
     * ({@link #capturedWeight}), capped at {@link #MAX_AUTOMATIC}. For wide windows this is about ceil(3 sigma)
     * (the texels' cells, not only their centres, must lie within 3 sigma); for narrow ones the nearest texel
     * alone suffices: sigma = 0.64 texels (a 65 um patch, 4 sigma_s = 65 um) gives R = 2, the 9.2 um
     * Elaphe-like patch (sigma = 0.09) R = 0.
     */
    public static int automatic(double sigmaTexels) {
        for (int r = 0; r < MAX_AUTOMATIC; r++) {
            if (capturedWeight(sigmaTexels, r) >= AUTOMATIC_CAPTURE) {
                return r;
            }
        }
        return MAX_AUTOMATIC;
    }

    /**
     * The share of the window's weight that the (2R + 1) texels around round(s) capture on one axis, in the worst
     * case: 1 - max_s (weight of the texels left out) / max_s (weight of all texels), G = {@link
     * CoherenceWindow#weight}. (Relative to the largest total rather than to the total at the same s: half-way
     * between the texels of a narrow window both neighbours weigh the same, negligible amount.) The 2-D share is
     * at least the product of the two axes' shares (the window is separable).
     */
    public static double capturedWeight(double sigmaTexels, int radius) {
        double largestLeftOut = 0;
        double largestTotal = 0;
        int reach = radius + (int) Math.ceil(12 * sigmaTexels) + 2; // weights beyond 12 sigma are below 1e-31
        for (int k = 0; k <= 200; k++) {
            double f = k / 400.0; // s - round(s) in [0, 1/2]; the window is symmetric
            double leftOut = 0;
            double total = 0;
            for (int j = -reach; j <= reach; j++) {
                double weight = CoherenceWindow.weight(j - f, sigmaTexels);
                total += weight;
                if (Math.abs(j) > radius) {
                    leftOut += weight;
                }
            }
            largestLeftOut = Math.max(largestLeftOut, leftOut);
            largestTotal = Math.max(largestTotal, total);
        }
        return 1.0 - largestLeftOut / largestTotal;
    }
}
