package diffract.optics.windows;

/**
 * The coherence window under one surface point, averaged over the pixel's footprint on the skin
 * ({@link WindowPlacement#LOCAL}; docs/design/theory.md, "The window under each surface point"). With the scan periodic of
 * extent L, a window centred at x0 gives, up to a global phase, P(s; x0) = sum_m G(s - m) T_m exp(2 pi i m . x0 / L),
 * so
 * <pre>
 *   |P(s; x0)|^2 = sum_{m, m'} G(s - m) G(s - m') T_m conj(T_m') exp(2 pi i (m - m') . x0 / L),
 * </pre>
 * and the average over x0 spread by the footprint multiplies each pair by the footprint's characteristic function at
 * (m - m') / L ({@link SkinFootprint#pairFactor}). A point footprint gives the fixed window at x0 (the thesis' at
 * x0 = 0); one that covers a period (a box of width L, or a Gaussian much wider than L) leaves the diagonal, the
 * averaged window.
 *
 * @param centreXUm x0 along the scan's columns, um (any value: the scan is periodic)
 * @param centreYUm x0 along its rows, um
 * @param footprint the spread of x0 over the pixel
 */
public record LocalWindow(double centreXUm, double centreYUm, SkinFootprint footprint) {
    public LocalWindow {
        if (!Double.isFinite(centreXUm) || !Double.isFinite(centreYUm)) {
            throw new IllegalArgumentException("the window's centre must be finite, got " + centreXUm + ", " + centreYUm);
        }
        if (footprint == null) {
            throw new NullPointerException("the footprint is required (SkinFootprint.POINT for none)");
        }
    }

    /** The window at x0 with no footprint: the fixed window there. */
    public static LocalWindow at(double centreXUm, double centreYUm) {
        return new LocalWindow(centreXUm, centreYUm, SkinFootprint.POINT);
    }

    /**
     * sum_{m, m'} A_m conj(A_m') exp(2 pi i (m - m') . x0 / L) pairFactor((m - m') / L) of window amplitudes
     * A_k = (re[k], im[k]) at texel offsets (offX[k], offY[k]) from the window's anchor: only differences of texels
     * enter, so the anchor's own index drops out and the phases stay small.
     */
    public double power(double[] re, double[] im, int[] offX, int[] offY, int count, double extentXUm,
                        double extentYUm) {
        double fx = centreXUm / extentXUm;
        double fy = centreYUm / extentYUm;
        double sum = 0;
        for (int k = 0; k < count; k++) {
            sum += re[k] * re[k] + im[k] * im[k];
            for (int l = k + 1; l < count; l++) {
                int dx = offX[k] - offX[l];
                int dy = offY[k] - offY[l];
                double factor = footprint.pairFactor(dx / extentXUm, dy / extentYUm);
                if (factor == 0) {
                    continue;
                }
                double phase = -2.0 * Math.PI * (dx * (fx - Math.floor(fx)) + dy * (fy - Math.floor(fy)));
                // A_k conj(A_l) e^{i phase} + its conjugate (the pair (l, k)) = 2 Re(...)
                double pr = re[k] * re[l] + im[k] * im[l];
                double pi = im[k] * re[l] - re[k] * im[l];
                sum += 2.0 * factor * (pr * Math.cos(phase) - pi * Math.sin(phase));
            }
        }
        return sum;
    }
}
