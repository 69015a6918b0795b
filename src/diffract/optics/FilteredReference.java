package diffract.optics;

import diffract.colour.SpectralDensity;
import diffract.colour.Xyz;

import java.util.function.DoubleFunction;

/**
 * The filtered reference: the defined value of a pixel, i.e. the relative BRDF averaged over the pixel's footprint
 * and the light's directions and integrated over wavelength against D65 x CIE 1931 exactly (docs/filtering.md),
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
 * k x k sub-boxes, k = 1, 2, 4, ..., until the pixel changes by less than {@link #PIXEL_TOLERANCE}. The light's
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
    static final double LOBE_TOLERANCE = 1e-5;
    /** Pairs of texels are kept down to this weight (relative to the product of their coefficients). */
    static final double PAIR_THRESHOLD = 1e-8;
    /** A lobe reaches as far as this many standard deviations (the tail beyond holds 1e-9 of it). */
    static final double REACH_SIGMAS = 6.0;
    private static final int MAX_SUBDIVISION = 16;

    private final GaussianLobes lobes;
    private final SpectralDensity density;
    private final double extentXUm;
    private final double extentYUm;
    private final double sigmaFPerUm;
    private final double refractiveIndex;
    private final FresnelModel fresnel;

    /** Over the band and with the mirror's normalisation of {@code spectral}. */
    public FilteredReference(ExactSpectrum spectrum, CoherenceWindow window, SpectralSettings spectral,
                             double refractiveIndex, FresnelModel fresnel) {
        this.lobes = new GaussianLobes(spectrum, spectrum.sigmaTexelsX(), spectrum.sigmaTexelsY(),
                window.averaged() ? GaussianLobes.WHOLE_TEXELS : PAIR_THRESHOLD);
        this.density = new SpectralDensity(spectral.lambdaMinNm(), spectral.lambdaMaxNm(), spectral.normalisation());
        this.extentXUm = spectrum.extentXUm();
        this.extentYUm = spectrum.extentYUm();
        this.sigmaFPerUm = window.sigmaFrequencyPerUm();
        this.refractiveIndex = refractiveIndex;
        this.fresnel = fresnel;
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
        double[] previous = subdivided(wi, light, x, y, half, 1);
        for (int k = 2; k <= MAX_SUBDIVISION; k *= 2) {
            double[] current = subdivided(wi, light, x, y, half, k);
            double scale = Math.max(Math.abs(current[0]), Math.max(Math.abs(current[1]), Math.abs(current[2])));
            boolean converged = true;
            for (int i = 0; i < 3; i++) {
                converged &= Math.abs(current[i] - previous[i]) <= PIXEL_TOLERANCE * scale + FLOOR;
            }
            previous = current;
            if (converged) {
                break;
            }
        }
        return new Xyz(previous[0], previous[1], previous[2]);
    }

    /** The pixel's box split into k x k sub-boxes, each averaged with C S W to first order about its centre. */
    private double[] subdivided(Direction wi, Covariance2 light, double x, double y, double half, int k) {
        double[] sum = new double[3];
        double sub = half / k;
        for (int a = 0; a < k; a++) {
            for (int b = 0; b < k; b++) {
                double sx = x - half + (2 * a + 1) * sub;
                double sy = y - half + (2 * b + 1) * sub;
                if (sx * sx + sy * sy >= 1) {
                    continue;
                }
                double[] v = box(wi, sx, sy, sub, light);
                for (int i = 0; i < 3; i++) {
                    sum[i] += v[i];
                }
            }
        }
        for (int i = 0; i < 3; i++) {
            sum[i] /= (double) k * k;
        }
        return sum;
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
        return GainFactor.gainTimesShadowing(wi, Direction.fromProjected(x, y), refractiveIndex, fresnel);
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
        double gain = GainFactor.gainTimesShadowing(wi, wr, refractiveIndex, fresnel);
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
        int step = lobes.hasPairs() ? 1 : 2;
        double[] total = new double[3];
        for (int tx = step == 2 ? evenAtOrAbove(range[0]) : range[0]; tx <= range[1]; tx += step) {
            for (int ty = step == 2 ? evenAtOrAbove(range[2]) : range[2]; ty <= range[3]; ty += step) {
                double cx = 0.5 * tx / extentXUm; // per um: mu = lambda_um (cx, cy)
                double cy = 0.5 * ty / extentYUm;
                double[] interval = LobeGeometry.lambdaIntervalNm(cx, cy, u, v, reachU, reachV, lambdaMin, lambdaMax);
                if (interval == null) {
                    continue;
                }
                GaussianLobes.Lobe lobe = lobes.lobe(tx, ty);
                if (lobe == null) {
                    continue;
                }
                double[] value = lobeIntegral(lobe, cx, cy, u, v, w, hx, hy, g, linear, interval[0], interval[1]);
                for (int i = 0; i < 3; i++) {
                    total[i] += value[i];
                }
            }
        }
        return total;
    }

    private static int evenAtOrAbove(int n) {
        return n % 2 == 0 ? n : n + 1;
    }

    /** The integral over [from, to] nm of f C S W A for one lobe. */
    private double[] lobeIntegral(GaussianLobes.Lobe lobe, double cx, double cy, double u, double v, double w,
                                  double hx, double hy, Covariance2 g, Linear linear, double from, double to) {
        boolean box = hx > 0 || hy > 0;
        double[] moments = new double[3];
        double[] weight = new double[2];
        DoubleFunction<double[]> integrand = lambdaNm -> {
            double[] f = new double[3];
            density.at(lambdaNm, f);
            double lambdaUm = lambdaNm * 1e-3;
            double k = 2 * Math.PI / lambdaUm;
            double sigmaUv = lambdaUm * sigmaFPerUm;
            double scale;
            if (box) {
                lobe.weightWithDerivative(k * w, weight);
                double weightW = k * weight[1]; // dW/dw
                LobeGeometry.boxMoments(sigmaUv, lambdaUm * cx, lambdaUm * cy, u, v, hx, hy, g, moments);
                scale = linear.gain() * weight[0] * moments[0]
                        + (linear.gainU() * weight[0] + linear.gain() * linear.wU() * weightW) * moments[1]
                        + (linear.gainV() * weight[0] + linear.gain() * linear.wV() * weightW) * moments[2];
            } else {
                scale = linear.gain() * lobe.weight(k * w)
                        * LobeGeometry.averagedLobe(sigmaUv, lambdaUm * cx, lambdaUm * cy, u, v, 0, 0, g, false);
            }
            f[0] *= scale;
            f[1] *= scale;
            f[2] *= scale;
            return f;
        };
        return GaussKronrod.integrate(integrand, 3, from, to, LOBE_TOLERANCE, 1e-3 * FLOOR);
    }

    private static double square(double x) {
        return x * x;
    }
}
