package diffract.optics.spectra;

import diffract.optics.numerics.ShiftedDft;
import diffract.optics.patches.HeightField;
import diffract.optics.windows.CoherenceWindow;
import diffract.optics.windows.WindowPlacement;
import diffract.util.MemoryEstimate;

import java.util.Locale;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentMap;

/**
 * The yardstick: the windowed spectrum of p = exp(i a h), a = k w, without the thesis' truncated series, float32
 * storage or 3 x 3 window.
 *
 * <p>How exp(i a h) is evaluated exactly and still fast: a FFT of exp(i a h) for every pixel and wavelength would
 * cost hours per map, so we expand around the nearest of a grid of centres a_j = j / max|h|:
 * exp(i a h) = exp(i a_j h) sum_n (i (a - a_j) h)^n / n!, with |a - a_j| max|h| <= 1/2. The transforms
 * E_{j,n} = fftshift(ifft2(exp(i a_j h) (i h)^n)) are computed once per centre in double. Unlike the thesis' series
 * around 0, whose terms grow like e^x before they cancel, every term here is at most (1/2)^n / n! of |P|'s scale,
 * so nothing cancels, and 16 terms leave a remainder below (1/2)^16 / 16! = 7e-19: exact to double precision.
 * (Tests compare it with a direct, naive DFT of exp(i a h) to 1e-12.)
 *
 * <p>The Gaussian window is summed over every texel whose weight is at least 1e-12: as complex amplitudes (the window
 * fixed at the DFT's origin) or, averaged over the window's position, as powers G^2 |T_m|^2 ({@link WindowPlacement}).
 */
public final class ExactSpectrum implements PatchSpectrum, TexelCoefficients {
    /** Terms per centre: (1/2)^16 / 16! < 1e-18. */
    static final int ORDERS_PER_CENTRE = 15;
    /** The window is summed until its weights fall below this (1e-12: beyond it they change no double sum). */
    public static final double WINDOW_CUTOFF = 1e-12;

    private final HeightField field;
    private final double[] heightsUm;
    private final double centreSpacing;
    private final double sigmaTexelsX;
    private final double sigmaTexelsY;
    private final int radiusX;
    private final int radiusY;
    private final boolean averaged;
    private final ConcurrentMap<Integer, double[][]> expansions = new ConcurrentHashMap<>();
    /** Per phase centre, per texel: the largest |T_m(a)| within half a centre spacing of it. */
    private final ConcurrentMap<Integer, double[]> bounds = new ConcurrentHashMap<>();

    /**
     * The heap the spectrum holds after looking up every direction of a BRDF map lit from theta_i, over the
     * wavelengths [lambdaMinNm, lambdaMaxNm]: the expansions of every centre a_j between the map's extreme phases
     * a = k w (w = -(cos theta_i + cos theta_r) from -(1 + cos theta_i) to -cos theta_i), each
     * ORDERS_PER_CENTRE + 1 double complex transforms of the patch and a bound per texel (264 bytes per sample), kept
     * for the whole map;
     * and the work arrays of the expansions computed at once (one per thread: the centre field, the transform and
     * its shifted copy, 48 bytes per sample).
     */
    public static MemoryEstimate memory(HeightField meanSubtracted, double thetaIDeg, double lambdaMinNm,
                                        double lambdaMaxNm) {
        double maxAbs = meanSubtracted.maxAbsHeightUm();
        double cosI = Math.cos(Math.toRadians(thetaIDeg));
        long centres = 1;
        if (maxAbs > 0) {
            double aLowest = -(1 + cosI) * 2 * Math.PI / (lambdaMinNm * 1e-3); // 1/um
            double aHighest = -cosI * 2 * Math.PI / (lambdaMaxNm * 1e-3);
            centres = Math.round(Math.rint(aHighest * maxAbs) - Math.rint(aLowest * maxAbs)) + 1;
        }
        long samples = (long) meanSubtracted.rows() * meanSubtracted.cols();
        long threads = Math.min(centres, Runtime.getRuntime().availableProcessors());
        long perCentre = (16L * (ORDERS_PER_CENTRE + 1) + 8) * samples;
        return MemoryEstimate.of(String.format(Locale.ROOT, "exact spectrum: %d phase centres x %d transforms of %dx%d",
                        centres, ORDERS_PER_CENTRE + 1, meanSubtracted.cols(), meanSubtracted.rows()),
                        perCentre > Long.MAX_VALUE / centres ? Long.MAX_VALUE : centres * perCentre)
                .plus("its work arrays", 48L * samples * threads);
    }

    /** @param meanSubtracted the patch, mean removed */
    public ExactSpectrum(HeightField meanSubtracted, CoherenceWindow window) {
        this.field = meanSubtracted;
        this.heightsUm = meanSubtracted.heightsUm();
        double maxAbs = meanSubtracted.maxAbsHeightUm();
        this.centreSpacing = maxAbs > 0 ? 1.0 / maxAbs : Double.POSITIVE_INFINITY;
        this.sigmaTexelsX = window.sigmaTexels(extentXUm());
        this.sigmaTexelsY = window.sigmaTexels(extentYUm());
        double sigmas = CoherenceWindow.sigmasForCutoff(WINDOW_CUTOFF);
        this.radiusX = (int) Math.ceil(sigmas * sigmaTexelsX) + 1;
        this.radiusY = (int) Math.ceil(sigmas * sigmaTexelsY) + 1;
        this.averaged = window.averaged();
    }

    @Override
    public double extentXUm() {
        return field.widthUm();
    }

    @Override
    public double extentYUm() {
        return field.heightExtentUm();
    }

    @Override
    public double power(double u, double v, double w, double lambdaUm) {
        if (averaged) {
            return windowSum(u, v, w, lambdaUm, true)[0];
        }
        double[] p = transformAt(u, v, w, lambdaUm);
        return p[0] * p[0] + p[1] * p[1];
    }

    /** Whether the window is averaged over its position (texels add as powers). */
    boolean averaged() {
        return averaged;
    }

    /** The complex P (Re, Im) of the window at the DFT's origin, at the lookup of (u, v) for a = 2 pi w / lambda. */
    double[] transformAt(double u, double v, double w, double lambdaUm) {
        return windowSum(u, v, w, lambdaUm, false);
    }

    /** The window's sum of the texels' powers G^2 |T_m|^2 ({power, 0}), or of their amplitudes G T_m ({Re, Im}). */
    private double[] windowSum(double u, double v, double w, double lambdaUm, boolean powers) {
        double sx = u * extentXUm() / lambdaUm;
        double sy = v * extentYUm() / lambdaUm;
        double a = 2.0 * Math.PI / lambdaUm * w;
        int centre = Double.isInfinite(centreSpacing) ? 0 : (int) Math.rint(a / centreSpacing);
        double delta = Double.isInfinite(centreSpacing) ? 0 : a - centre * centreSpacing;
        double[][] e = expansions.computeIfAbsent(centre, this::expand);
        double[] coefficients = TaylorCoefficients.of(delta, ORDERS_PER_CENTRE);
        int cols = field.cols();
        int rows = field.rows();
        int anchorX = (int) Math.floor(sx + 0.5);
        int anchorY = (int) Math.floor(sy + 0.5);
        WindowSum window = new WindowSum(powers);
        for (int j = anchorY - radiusY; j <= anchorY + radiusY; j++) {
            int row = j + rows / 2;
            if (row < 0 || row >= rows) {
                continue;
            }
            double weightY = CoherenceWindow.weight(j - sy, sigmaTexelsY);
            if (weightY < WINDOW_CUTOFF) {
                continue;
            }
            for (int i = anchorX - radiusX; i <= anchorX + radiusX; i++) {
                int col = i + cols / 2;
                if (col < 0 || col >= cols) {
                    continue;
                }
                double weight = weightY * CoherenceWindow.weight(i - sx, sigmaTexelsX);
                if (weight < WINDOW_CUTOFF) {
                    continue;
                }
                int index = 2 * (row * cols + col);
                double sumRe = 0;
                double sumIm = 0;
                for (int n = 0; n <= ORDERS_PER_CENTRE; n++) {
                    sumRe += coefficients[n] * e[n][index];
                    sumIm += coefficients[n] * e[n][index + 1];
                }
                window.add(weight, sumRe, sumIm);
            }
        }
        return window.result();
    }

    /** sigma_f in texels along x and y (the window this spectrum sums with). */
    public double sigmaTexelsX() {
        return sigmaTexelsX;
    }

    public double sigmaTexelsY() {
        return sigmaTexelsY;
    }

    @Override
    public int rows() {
        return field.rows();
    }

    @Override
    public int cols() {
        return field.cols();
    }

    @Override
    public double maxAbsHeightUm() {
        return field.maxAbsHeightUm();
    }

    /**
     * The exact coefficient T_m(a) = DFT(exp(i a h))(m) of texel m, the quantity the window sums in
     * {@link #transformAt} (for the lobe decomposition of the filtered reference).
     */
    @Override
    public Texel texel(int mx, int my) {
        int cols = field.cols();
        int rows = field.rows();
        if (!TexelCoefficients.inBand(mx, my, rows, cols)) {
            return null;
        }
        int index = 2 * ((my + rows / 2) * cols + mx + cols / 2);
        return new Texel() {
            private int cachedCentre = Integer.MIN_VALUE;
            private double[][] e;

            /** sum_n delta^n / n! E_{j,n}(texel), and its derivative sum_n delta^(n-1) / (n-1)! E_{j,n}. */
            @Override
            public void sum(double a, double[] out, boolean derivative) {
                int centre = Double.isInfinite(centreSpacing) ? 0 : (int) Math.rint(a / centreSpacing);
                double delta = Double.isInfinite(centreSpacing) ? 0 : a - centre * centreSpacing;
                if (centre != cachedCentre) {
                    e = expansions.computeIfAbsent(centre, ExactSpectrum.this::expand);
                    cachedCentre = centre;
                }
                double c = 1.0;
                double re = e[0][index];
                double im = e[0][index + 1];
                double dRe = 0;
                double dIm = 0;
                for (int n = 1; n <= ORDERS_PER_CENTRE; n++) {
                    if (derivative) {
                        dRe += c * e[n][index];
                        dIm += c * e[n][index + 1];
                    }
                    c *= delta / n;
                    re += c * e[n][index];
                    im += c * e[n][index + 1];
                }
                out[0] = re;
                out[1] = im;
                if (derivative) {
                    out[2] = dRe;
                    out[3] = dIm;
                }
            }
        };
    }

    /**
     * An upper bound on |T_m(a)|^2 for texel (mx, my) over phases a in [aLo, aHi]: around each phase centre a_j the
     * expansion gives |T_m(a_j + delta)| &lt;= sum_n |delta|^n / n! |E_{j,n}(m)| with |delta| at most half the centre
     * spacing (plus the series' remainder, below 1e-18). 0 outside the stored band.
     */
    public double texelBound(int mx, int my, double aLo, double aHi) {
        int cols = field.cols();
        int rows = field.rows();
        if (!TexelCoefficients.inBand(mx, my, rows, cols)) {
            return 0;
        }
        int index = (my + rows / 2) * cols + mx + cols / 2;
        int first = Double.isInfinite(centreSpacing) ? 0 : (int) Math.rint(aLo / centreSpacing);
        int last = Double.isInfinite(centreSpacing) ? 0 : (int) Math.rint(aHi / centreSpacing);
        double max = 0;
        for (int centre = first; centre <= last; centre++) {
            max = Math.max(max, bounds.computeIfAbsent(centre, this::bounds)[index]);
        }
        return max * max;
    }

    /** Per texel, sum_n r^n / n! |E_{j,n}| with r half the centre spacing, rounded up by 1e-12 of itself. */
    private double[] bounds(int centre) {
        double[][] e = expansions.computeIfAbsent(centre, this::expand);
        double r = Double.isInfinite(centreSpacing) ? 0 : 0.5 * centreSpacing;
        int texels = field.rows() * field.cols();
        double[] out = new double[texels];
        for (int t = 0; t < texels; t++) {
            double c = 1;
            double sum = 0;
            for (int n = 0; n <= ORDERS_PER_CENTRE; n++) {
                sum += c * Math.hypot(e[n][2 * t], e[n][2 * t + 1]);
                c *= r / (n + 1);
            }
            out[t] = sum * (1 + 1e-12) + 1e-18;
        }
        return out;
    }

    /** E_{j,n} = fftshift(ifft2(exp(i a_j h) (i h)^n)), n = 0..ORDERS_PER_CENTRE (PhaseCentres' arithmetic). */
    private double[][] expand(int centre) {
        double aj = Double.isInfinite(centreSpacing) ? 0 : centre * centreSpacing;
        double[] f = PhaseCentres.centreField(heightsUm, aj);
        double[][] out = new double[ORDERS_PER_CENTRE + 1][];
        for (int n = 0; n <= ORDERS_PER_CENTRE; n++) {
            if (n > 0) {
                PhaseCentres.multiplyByIH(f, heightsUm);
            }
            out[n] = ShiftedDft.inverse(f, field.rows(), field.cols());
        }
        return out;
    }
}
