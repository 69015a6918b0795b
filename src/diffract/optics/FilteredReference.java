package diffract.optics;

import diffract.colour.SpectralDensity;
import diffract.colour.Xyz;
import diffract.optics.patches.Direction;
import diffract.optics.illumination.Footprint;
import diffract.optics.illumination.LightSource;
import diffract.optics.illumination.LobeGeometry;
import diffract.optics.lobes.GaussianLobes;
import diffract.optics.lobes.LobeWeights;
import diffract.optics.numerics.Covariance2;
import diffract.optics.numerics.GaussKronrod;
import diffract.optics.settings.GainModel;
import diffract.optics.settings.SpectralSettings;
import diffract.optics.spectra.ExactSpectrum;
import diffract.optics.windows.CoherenceWindow;

import java.util.function.DoubleFunction;

/**
 * The filtered reference: the defined value of a pixel, i.e. the relative BRDF averaged over the pixel's footprint
 * and the light's directions and integrated over wavelength against D65 x CIE 1931 exactly (docs/design/filtering.md),
 * from the exact coefficients of {@link ExactSpectrum} (no Taylor series, no float32, no window truncation):
 * <pre>
 *   XYZ = sum_c integral d lambda f(lambda) average over the footprint of [C S W_c(k w) lobe_c],
 * </pre>
 * with the lobes W_c of {@link GaussianLobes} (with the window averaged over its position, one lobe per texel,
 * W_m = |T_m|^2, exactly; fixed at the DFT's origin, pairs down to weight {@link #PAIR_THRESHOLD}), f the normalised
 * D65 x CMF density ({@link SpectralDensity}) and each lobe averaged over the footprint analytically: per axis a
 * Gaussian of variance (lambda sigma_f)^2 / 2 plus the light's variance, averaged over the box by a difference of
 * erf; a light covariance that is not axis-aligned is split into a diagonal part and a rank-one part
 * ({@link Covariance2#diagonalPlusRankOne}) integrated numerically along its direction. The wavelength integral of
 * each lobe is globally adaptive Gauss-Kronrod over the part of the band where the lobe comes within
 * {@link #REACH_SIGMAS} standard deviations of the footprint.
 *
 * <p>The gain factor C, the shadowing S and w (in T_m(k w)) vary slowly over a pixel: within a (sub-)box the product
 * C S W_c is taken to first order about the box's centre (its value there, its gradient from the box's edges, and
 * dW_c / dw exactly), integrated against the lobe's first moments over the box (also exact). The box is split into
 * quarters, and each quarter again where splitting it changes its value by more than {@link #PIXEL_TOLERANCE} of the
 * pixel's largest value (adaptive: only where an order or a fast change of W crosses), to 16 x 16 at most. With the
 * window averaged over its position each box sums its whole-texel lobes from the largest bound down and leaves out
 * those whose bounds add up to less than {@link #SKIP_TOLERANCE} of it. The light's
 * directions leave C, S and w at the light's centre (the definition of {@link LightSource}).
 *
 * <p>Tolerance: every tristimulus value of a pixel to about {@link #PIXEL_TOLERANCE} relative (plus {@link #FLOOR}
 * of white), held to brute-force supersampling by FilteredReferenceTest.
 */
public final class FilteredReference {
    /** The relative change between sub-box levels at which a pixel is accepted. */
    public static final double PIXEL_TOLERANCE = 1e-4;
    /** Absolute floor of a pixel's tolerance, as a fraction of D65 white (Y = 1). */
    public static final double FLOOR = 1e-10;
    /** Each lobe's wavelength integral, relative to the lobe (bounding the 7-point rule's error, |K15 - G7|). */
    static final double LOBE_TOLERANCE = 1e-4;
    /** Pairs of texels are kept down to this weight (relative to the product of their coefficients). */
    static final double PAIR_THRESHOLD = 1e-8;
    /** A lobe reaches as far as this many standard deviations (the tail beyond holds 1e-9 of it). */
    static final double REACH_SIGMAS = 6.0;
    private static final int MAX_SUBDIVISION = 16;
    /**
     * Whole-texel lobes are integrated from the largest bound down; the rest are left out once their bounds add up to
     * less than this fraction of the pixel's largest value so far (100 times below {@link #PIXEL_TOLERANCE}).
     */
    static final double SKIP_TOLERANCE = 1e-6;

    private final LobeWeights weights;
    private final SpectralDensity density;
    /** Per nanometre cell of the band from floor(lambda_min): an upper bound on f_X + f_Y + f_Z over the cell. */
    private final double[] densityBound;
    private final double extentXUm;
    private final double extentYUm;
    private final double sigmaFPerUm;

    /** Over the band and with the mirror's normalisation of {@code spectral}. */
    public FilteredReference(ExactSpectrum spectrum, CoherenceWindow window, SpectralSettings spectral,
                             double refractiveIndex, GainModel gain) {
        this(LobeWeights.scalar(spectrum, window.averaged() ? GaussianLobes.WHOLE_TEXELS : PAIR_THRESHOLD,
                refractiveIndex, gain), spectrum.extentXUm(), spectrum.extentYUm(), window, spectral);
    }

    /** The lobes of a patch of L_x x L_y weighed by {@code weights}, over the band of {@code spectral}. */
    FilteredReference(LobeWeights weights, double extentXUm, double extentYUm, CoherenceWindow window,
                      SpectralSettings spectral) {
        this.weights = weights;
        this.density = new SpectralDensity(spectral.lambdaMinNm(), spectral.lambdaMaxNm(), spectral.normalisation());
        this.densityBound = densityBound(density);
        this.extentXUm = extentXUm;
        this.extentYUm = extentYUm;
        this.sigmaFPerUm = window.sigmaFrequencyPerUm();
    }

    /**
     * Pixel (column, row) of an S x S BRDF map (the convention of {@link BrdfMap}) for the light at omega_i with
     * (u, v) covariance {@code light} ({@link LightSource#uvCovariance}): the average over the pixel's square.
     * Pixels whose centre lies outside the unit disk are black, as in the point-sampled map; within a pixel, the
     * part outside the disk contributes 0.
     */
    public Xyz mapPixel(Direction wi, Covariance2 light, int column, int row, int size) {
        double x = BrdfMap.xOf(column, size);
        double y = BrdfMap.yOf(row, size);
        if (x * x + y * y >= 1) {
            return new Xyz(0, 0, 0);
        }
        double half = 1.0 / size;
        double[] whole = boxInDisk(wi, light, x, y, half);
        double[] children = new double[3];
        double[][] quarters = quarters(wi, light, x, y, half, children);
        double scale = Math.max(Math.abs(children[0]), Math.max(Math.abs(children[1]), Math.abs(children[2])));
        double tolerance = PIXEL_TOLERANCE * scale + FLOOR;
        double[] v = converged(whole, children, tolerance) ? children
                : refined(wi, light, x, y, half / 2, quarters, tolerance, 2);
        return new Xyz(v[0], v[1], v[2]);
    }

    /**
     * The box about (x, y) of half-width {@code half}, split into its four quarters until each quarter's split
     * changes its value by at most the pixel's tolerance (adaptive: only the quarters an order crosses are split
     * further), down to {@link #MAX_SUBDIVISION} quarters per side of the pixel. The quarters' values are given.
     */
    private double[] refined(Direction wi, Covariance2 light, double x, double y, double half, double[][] quarterValues,
                             double tolerance, int level) {
        double[] sum = new double[3];
        int q = 0;
        for (int a = -1; a <= 1; a += 2) {
            for (int b = -1; b <= 1; b += 2) {
                double cx = x + a * half;
                double cy = y + b * half;
                double[] value = quarterValues[q++];
                if (level < MAX_SUBDIVISION) {
                    double[] children = new double[3];
                    double[][] next = quarters(wi, light, cx, cy, half, children);
                    value = converged(value, children, tolerance) ? children
                            : refined(wi, light, cx, cy, half / 2, next, tolerance, 2 * level);
                }
                for (int i = 0; i < 3; i++) {
                    sum[i] += 0.25 * value[i];
                }
            }
        }
        return sum;
    }

    /** The four quarters of the box about (x, y) of half-width {@code half}: their values, and their mean into mean. */
    private double[][] quarters(Direction wi, Covariance2 light, double x, double y, double half, double[] mean) {
        double[][] out = new double[4][];
        int q = 0;
        for (int a = -1; a <= 1; a += 2) {
            for (int b = -1; b <= 1; b += 2) {
                out[q] = boxInDisk(wi, light, x + a * half / 2, y + b * half / 2, half / 2);
                for (int i = 0; i < 3; i++) {
                    mean[i] += 0.25 * out[q][i];
                }
                q++;
            }
        }
        return out;
    }

    private static boolean converged(double[] coarse, double[] fine, double tolerance) {
        for (int i = 0; i < 3; i++) {
            if (Math.abs(fine[i] - coarse[i]) > tolerance) {
                return false;
            }
        }
        return true;
    }

    /** The box with C S W to first order about its centre; 0 where its centre lies outside the unit disk. */
    private double[] boxInDisk(Direction wi, Covariance2 light, double x, double y, double half) {
        return x * x + y * y >= 1 ? new double[3] : box(wi, x, y, half, light);
    }

    /** The average over the square of half-width h about (x, y) in the projected plane of omega_r. */
    private double[] box(Direction wi, double x, double y, double h, Covariance2 light) {
        Direction wr = Direction.fromProjected(x, y);
        double gain = gainAt(wi, x, y);
        if (gain == 0) {
            return new double[3];
        }
        // u = -omega_i.x - x: d/du = -d/dx; secants across the box (one-sided where a neighbour leaves the disk)
        double gainU = -secant(wi, x, y, h, 0, true);
        double gainV = -secant(wi, x, y, h, 1, true);
        double wU = -secant(wi, x, y, h, 0, false);
        double wV = -secant(wi, x, y, h, 1, false);
        double u = -wi.x() - wr.x();
        double v = -wi.y() - wr.y();
        double w = -wi.z() - wr.z();
        return lobeSum(u, v, w, new Footprint(h, h, light), new Linear(gain, gainU, gainV, wU, wV));
    }

    private double gainAt(Direction wi, double x, double y) {
        if (x * x + y * y >= 1) {
            return Double.NaN;
        }
        return weights.gain(wi, Direction.fromProjected(x, y));
    }

    private static double wAt(Direction wi, double x, double y) {
        if (x * x + y * y >= 1) {
            return Double.NaN;
        }
        return -wi.z() - Math.sqrt(1 - x * x - y * y);
    }

    /** d/dx (axis 0) or d/dy of C S (gain) or w by the secant over [c - h, c + h], one-sided near the rim. */
    private double secant(Direction wi, double x, double y, double h, int axis, boolean gain) {
        double dx = axis == 0 ? h : 0;
        double dy = axis == 0 ? 0 : h;
        double centre = gain ? gainAt(wi, x, y) : wAt(wi, x, y);
        double plus = gain ? gainAt(wi, x + dx, y + dy) : wAt(wi, x + dx, y + dy);
        double minus = gain ? gainAt(wi, x - dx, y - dy) : wAt(wi, x - dx, y - dy);
        if (!Double.isNaN(plus) && !Double.isNaN(minus)) {
            return (plus - minus) / (2 * h);
        }
        if (!Double.isNaN(plus)) {
            return (plus - centre) / h;
        }
        if (!Double.isNaN(minus)) {
            return (centre - minus) / h;
        }
        return 0;
    }

    /**
     * The footprint's average around the direction pair (its box centred on their (u, v)), with C S and w at the
     * centre: {X, Y, Z}. For a point, or for the light alone, this is the defined value; a box is averaged with C S
     * and W taken constant over it (use {@link #mapPixel} for map pixels).
     */
    public double[] at(Direction wi, Direction wr, Footprint footprint) {
        double gain = weights.gain(wi, wr);
        if (gain == 0) {
            return new double[3];
        }
        double u = -wi.x() - wr.x();
        double v = -wi.y() - wr.y();
        double w = -wi.z() - wr.z();
        return lobeSum(u, v, w, footprint, new Linear(gain, 0, 0, 0, 0));
    }

    /**
     * C S W_c to first order over a box about its centre: C S = gain + gainU (u' - u) + gainV (v' - v), and
     * w = w_c + wU (u' - u) + wV (v' - v) inside W_c(k w).
     */
    private record Linear(double gain, double gainU, double gainV, double wU, double wV) {
    }

    /** sum over lobes of the wavelength integral of f C S W_c A_c at the footprint's centre (u, v) and w. */
    private double[] lobeSum(double u, double v, double w, Footprint footprint, Linear linear) {
        Covariance2 g = footprint.gaussian();
        double hx = footprint.halfWidthU();
        double hy = footprint.halfWidthV();
        if (!footprint.hasBox() || g.isDiagonal()) {
            return lobeSumSeparable(u, v, w, hx, hy, g, linear);
        }
        // the box needs a diagonal Gaussian: integrate the rank-one rest along its direction
        double[] split = g.diagonalPlusRankOne();
        Covariance2 diagonal = new Covariance2(split[0], 0, split[1]);
        double dx = split[2];
        double dy = split[3];
        double sigma = Math.sqrt(split[4]);
        double reach = REACH_SIGMAS * sigma;
        DoubleFunction<double[]> alongLight = t -> {
            double weight = Math.exp(-0.5 * t * t / (sigma * sigma)) / (Math.sqrt(2 * Math.PI) * sigma);
            double[] value = lobeSumSeparable(u + t * dx, v + t * dy, w, hx, hy, diagonal, linear);
            for (int i = 0; i < 3; i++) {
                value[i] *= weight;
            }
            return value;
        };
        return GaussKronrod.integrate(alongLight, 3, -reach, reach, 0.1 * PIXEL_TOLERANCE, FLOOR);
    }

    /** The lobe sum for a box and a Gaussian that is diagonal whenever there is a box. */
    private double[] lobeSumSeparable(double u, double v, double w, double hx, double hy, Covariance2 g,
                                      Linear linear) {
        double lambdaMin = density.lambdaMinNm();
        double lambdaMax = density.lambdaMaxNm();
        // the widest a lobe gets (at lambda_max), per axis, and how far it reaches from the footprint's centre
        double lobeVariance = 0.5 * square(lambdaMax * 1e-3 * sigmaFPerUm);
        double reachU = hx + REACH_SIGMAS * Math.sqrt(lobeVariance + g.xx());
        double reachV = hy + REACH_SIGMAS * Math.sqrt(lobeVariance + g.yy());
        int[] range = LobeGeometry.candidateRange(u, v, reachU, reachV, extentXUm, extentYUm, lambdaMin, lambdaMax);
        if (!weights.hasPairs()) {
            return wholeTexelSum(u, v, w, hx, hy, g, linear, range, reachU, reachV);
        }
        int step = 1;
        double[] total = new double[3];
        for (int tx = range[0]; tx <= range[1]; tx += step) {
            for (int ty = range[2]; ty <= range[3]; ty += step) {
                double cx = 0.5 * tx / extentXUm; // per um: mu = lambda_um (cx, cy)
                double cy = 0.5 * ty / extentYUm;
                double[] interval = LobeGeometry.lambdaIntervalNm(cx, cy, u, v, reachU, reachV, lambdaMin, lambdaMax);
                if (interval == null) {
                    continue;
                }
                LobeWeights.Lobe lobe = weights.lobe(tx, ty);
                if (lobe == null) {
                    continue;
                }
                double[] value = lobeIntegral(lobe, cx, cy, u, v, w, hx, hy, g, linear, interval[0], interval[1],
                        1e-3 * FLOOR);
                for (int i = 0; i < 3; i++) {
                    total[i] += value[i];
                }
            }
        }
        return total;
    }

    /**
     * f_X + f_Y + f_Z is a quadratic between whole nanometres (linear D65 times linear CMFs): sampled at 9 points of
     * each cell, its largest value times 1.05 bounds it there.
     */
    private static double[] densityBound(SpectralDensity density) {
        double first = Math.floor(density.lambdaMinNm());
        int cells = (int) Math.ceil(density.lambdaMaxNm() - first) + 1;
        double[] out = new double[cells];
        double[] f = new double[3];
        for (int i = 0; i < cells; i++) {
            double max = 0;
            for (int k = 0; k <= 8; k++) {
                density.at(Math.min(density.lambdaMaxNm(), Math.max(density.lambdaMinNm(), first + i + k / 8.0)), f);
                max = Math.max(max, f[0] + f[1] + f[2]);
            }
            out[i] = 1.05 * max;
        }
        return out;
    }

    /** An upper bound on the integral of f_X + f_Y + f_Z over [from, to] nm. */
    private double densityIntegralBound(double from, double to) {
        double first = Math.floor(density.lambdaMinNm());
        double sum = 0;
        for (int i = (int) Math.floor(from - first); i < densityBound.length && first + i < to; i++) {
            double lo = Math.max(from, first + i);
            double hi = Math.min(to, first + i + 1);
            if (hi > lo && i >= 0) {
                sum += densityBound[i] * (hi - lo);
            }
        }
        return sum;
    }

    /**
     * An upper bound on what the whole-texel lobe of texel (mx, my) over [from, to] nm adds to X + Y + Z: the
     * texel's largest |T_m|^2 over the phases k w the box reaches, the largest box average of a lobe of peak 1 (per
     * axis the box's sqrt(pi) sigma_uv / 2h and the widened peak, at the longest wavelength), the gain's largest value
     * over the box, a factor for the first-order change of W across it (Bernstein: |dW / da| stays within about
     * 2 max|h| W), and the density's integral.
     */
    private double lobeBound(int mx, int my, double cx, double cy, double u, double v, double w, double hx, double hy,
                             Covariance2 g, Linear linear, double from, double to) {
        double dw = Math.abs(linear.wU()) * hx + Math.abs(linear.wV()) * hy;
        double kHi = 2 * Math.PI / (from * 1e-3);
        double weight = weights.bound(mx, my, from, to, w, dw);
        if (weight == 0) {
            return 0;
        }
        double sigmaUv = to * 1e-3 * sigmaFPerUm;
        double lobeVariance = 0.5 * sigmaUv * sigmaUv;
        // the lobe's centre lambda c passes the box at a distance of at least gap_i along each axis
        double gapU = gap(u, hx, cx * from * 1e-3, cx * to * 1e-3);
        double gapV = gap(v, hy, cy * from * 1e-3, cy * to * 1e-3);
        double distance = Math.exp(-0.5 * (gapU * gapU / (lobeVariance + g.xx()) + gapV * gapV / (lobeVariance + g.yy())));
        double area = axisPeak(sigmaUv, hx, g.xx()) * axisPeak(sigmaUv, hy, g.yy()) * distance;
        double gain = Math.abs(linear.gain()) + Math.abs(linear.gainU()) * hx + Math.abs(linear.gainV()) * hy;
        double slope = weights.slope(kHi, dw);
        return gain * slope * weight * area * densityIntegralBound(from, to);
    }

    /** The distance between [u - h, u + h] and the interval between a and b (0 where they overlap). */
    private static double gap(double u, double h, double a, double b) {
        double lo = Math.min(a, b);
        double hi = Math.max(a, b);
        return Math.max(0, Math.max(lo - (u + h), (u - h) - hi));
    }

    /** The largest average over [u - h, u + h] of a lobe of peak 1 and spread sigmaUv widened by a variance. */
    private static double axisPeak(double sigmaUv, double h, double variance) {
        double peak = sigmaUv / Math.sqrt(sigmaUv * sigmaUv + 2 * variance);
        return h > 0 ? Math.min(peak, Math.sqrt(Math.PI) * sigmaUv / (2 * h)) : peak;
    }

    private static int evenAtOrAbove(int n) {
        return n % 2 == 0 ? n : n + 1;
    }

    /**
     * The lobes of whole texels (the window averaged over its position): every lobe the footprint can reach, each with
     * an upper bound on what it adds, integrated from the largest bound down until the bounds of those left add up to
     * less than {@link #SKIP_TOLERANCE} of the pixel's largest value so far.
     */
    private double[] wholeTexelSum(double u, double v, double w, double hx, double hy, Covariance2 g, Linear linear,
                                   int[] range, double reachU, double reachV) {
        double lambdaMin = density.lambdaMinNm();
        double lambdaMax = density.lambdaMaxNm();
        java.util.List<double[]> candidates = new java.util.ArrayList<>();
        for (int tx = evenAtOrAbove(range[0]); tx <= range[1]; tx += 2) {
            for (int ty = evenAtOrAbove(range[2]); ty <= range[3]; ty += 2) {
                double cx = 0.5 * tx / extentXUm;
                double cy = 0.5 * ty / extentYUm;
                double[] interval = LobeGeometry.lambdaIntervalNm(cx, cy, u, v, reachU, reachV, lambdaMin, lambdaMax);
                if (interval == null) {
                    continue;
                }
                double bound = lobeBound(tx / 2, ty / 2, cx, cy, u, v, w, hx, hy, g, linear, interval[0], interval[1]);
                if (bound > 0) {
                    candidates.add(new double[] {bound, tx, ty, interval[0], interval[1]});
                }
            }
        }
        candidates.sort((a, b) -> Double.compare(b[0], a[0]));
        double[] rest = new double[candidates.size() + 1];
        for (int i = candidates.size() - 1; i >= 0; i--) {
            rest[i] = rest[i + 1] + candidates.get(i)[0];
        }
        double[] total = new double[3];
        for (int i = 0; i < candidates.size(); i++) {
            double largest = Math.max(total[0], Math.max(total[1], total[2]));
            if (rest[i] <= SKIP_TOLERANCE * largest + 1e-3 * FLOOR) {
                break;
            }
            double[] c = candidates.get(i);
            int tx = (int) c[1];
            int ty = (int) c[2];
            LobeWeights.Lobe lobe = weights.lobe(tx, ty);
            if (lobe == null) {
                continue;
            }
            // each lobe's integral to LOBE_TOLERANCE of itself, or to 1e-5 of the pixel shared among the lobes:
            // together the small ones err by at most 1e-5 of the pixel
            double absolute = Math.max(1e-3 * FLOOR, 1e-5 * largest / candidates.size());
            double[] value = lobeIntegral(lobe, 0.5 * tx / extentXUm, 0.5 * ty / extentYUm, u, v, w, hx, hy, g,
                    linear, c[3], c[4], absolute);
            for (int k = 0; k < 3; k++) {
                total[k] += value[k];
            }
        }
        return total;
    }

    /** The integral over [from, to] nm of f C S W A for one lobe, to LOBE_TOLERANCE of itself or {@code absolute}. */
    private double[] lobeIntegral(LobeWeights.Lobe lobe, double cx, double cy, double u, double v, double w,
                                  double hx, double hy, Covariance2 g, Linear linear, double from, double to,
                                  double absolute) {
        boolean box = hx > 0 || hy > 0;
        double[] moments = new double[3];
        double[] weight = new double[2];
        DoubleFunction<double[]> integrand = lambdaNm -> {
            double[] f = new double[3];
            density.at(lambdaNm, f);
            double lambdaUm = lambdaNm * 1e-3;
            double sigmaUv = lambdaUm * sigmaFPerUm;
            double scale;
            if (box) {
                lobe.weightWithDerivative(lambdaUm, w, weight);
                double weightW = weight[1]; // dW/dw
                LobeGeometry.boxMoments(sigmaUv, lambdaUm * cx, lambdaUm * cy, u, v, hx, hy, g, moments);
                scale = linear.gain() * weight[0] * moments[0]
                        + (linear.gainU() * weight[0] + linear.gain() * linear.wU() * weightW) * moments[1]
                        + (linear.gainV() * weight[0] + linear.gain() * linear.wV() * weightW) * moments[2];
            } else {
                scale = linear.gain() * lobe.weight(lambdaUm, w)
                        * LobeGeometry.averagedLobe(sigmaUv, lambdaUm * cx, lambdaUm * cy, u, v, 0, 0, g, false);
            }
            f[0] *= scale;
            f[1] *= scale;
            f[2] *= scale;
            return f;
        };
        return GaussKronrod.integrate(integrand, 3, from, to, LOBE_TOLERANCE, absolute);
    }

    private static double square(double x) {
        return x * x;
    }
}
