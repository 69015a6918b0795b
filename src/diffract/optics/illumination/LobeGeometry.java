package diffract.optics.illumination;

import diffract.optics.numerics.Covariance2;
import diffract.optics.numerics.ErrorFunction;

/**
 * Where a Gaussian lobe is and what a footprint sees of it, in the (u, v) plane (docs/design/filtering.md, sections
 * 1-3). Lobe c of {@code GaussianLobes} sits at mu(lambda) = lambda (c_x / L_x, c_y / L_y): a
 * point moving on a ray from the specular direction as the wavelength grows, with isotropic variance sigma_uv^2 / 2,
 * sigma_uv = lambda sigma_f, and peak 1 (the window's). Shared by the filtered reference and the lobes method.
 */
public final class LobeGeometry {
    private static final double SQRT_PI = Math.sqrt(Math.PI);
    private static final double SQRT_TWO = Math.sqrt(2.0);
    private LobeGeometry() {
    }

    /**
     * The wavelengths (nm) at which a lobe moving as mu = lambda_um (cx, cy) (cx, cy per um) comes within
     * (reachU, reachV) of (u, v) on both axes, clipped to [lambdaMin, lambdaMax]; null if none.
     */
    public static double[] lambdaIntervalNm(double cx, double cy, double u, double v, double reachU, double reachV,
                                     double lambdaMinNm, double lambdaMaxNm) {
        double lo = lambdaMinNm;
        double hi = lambdaMaxNm;
        double[] axis = axisInterval(cx, u, reachU);
        if (axis == null) {
            return null;
        }
        lo = Math.max(lo, axis[0]);
        hi = Math.min(hi, axis[1]);
        axis = axisInterval(cy, v, reachV);
        if (axis == null) {
            return null;
        }
        lo = Math.max(lo, axis[0]);
        hi = Math.min(hi, axis[1]);
        return lo < hi ? new double[] {lo, hi} : null;
    }

    /**
     * The lobe centres that can come within (reachU, reachV) of (u, v) somewhere in the band, as doubled centres
     * {2 c_x min, 2 c_x max, 2 c_y min, 2 c_y max}: c = lambda^-1 (u L_x, v L_y) +- reach L / lambda, spanned by the
     * band's two ends (a box around the segment in texel space; {@link #lambdaIntervalNm} sorts out each lobe).
     */
    public static int[] candidateRange(double u, double v, double reachU, double reachV, double extentXUm,
                                       double extentYUm, double lambdaMinNm, double lambdaMaxNm) {
        double shortest = lambdaMinNm * 1e-3;
        double longest = lambdaMaxNm * 1e-3;
        double xLo = Math.min((u - reachU) * extentXUm / shortest, (u - reachU) * extentXUm / longest);
        double xHi = Math.max((u + reachU) * extentXUm / shortest, (u + reachU) * extentXUm / longest);
        double yLo = Math.min((v - reachV) * extentYUm / shortest, (v - reachV) * extentYUm / longest);
        double yHi = Math.max((v + reachV) * extentYUm / shortest, (v + reachV) * extentYUm / longest);
        return new int[] {(int) Math.floor(2 * xLo), (int) Math.ceil(2 * xHi), (int) Math.floor(2 * yLo),
            (int) Math.ceil(2 * yHi)};
    }

    /**
     * The wavelengths (nm) at which some lobe centred in the box [cx0, cx1] x [cy0, cy1] (per um) comes within reach of
     * (u, v), clipped to the band: an interval that holds {@link #lambdaIntervalNm} of every centre in the box (the
     * axes' conditions meet for each centre, so their intersection is wider than the union it bounds); null when
     * empty. Widened by a relative 1e-9, so that rounding never leaves out a centre on the box's edge.
     */
    public static double[] boxLambdaIntervalNm(double cx0, double cx1, double cy0, double cy1, double u, double v,
                                        double reachU, double reachV, double lambdaMinNm, double lambdaMaxNm) {
        double[] x = axisBoxInterval(cx0, cx1, u, reachU);
        double[] y = x == null ? null : axisBoxInterval(cy0, cy1, v, reachV);
        if (y == null) {
            return null;
        }
        double lo = Math.max(lambdaMinNm, Math.max(x[0], y[0]) * (1 - 1e-9));
        double hi = Math.min(lambdaMaxNm, Math.min(x[1], y[1]) * (1 + 1e-9));
        return lo < hi ? new double[] {lo, hi} : null;
    }

    /**
     * The lambda (nm, &gt; 0) at which some centre c in [c0, c1] has |lambda_um c - u| &lt;= reach: lambda c ranges over
     * [lambda c0, lambda c1], which meets [u - reach, u + reach] where lambda c0 &lt;= u + reach and lambda c1 &gt;=
     * u - reach; null when no lambda does.
     */
    private static double[] axisBoxInterval(double c0, double c1, double u, double reach) {
        double lo = 0;
        double hi = Double.POSITIVE_INFINITY;
        double upper = u + reach;
        if (c0 > 0) {
            hi = upper / c0 * 1e3;
        } else if (c0 < 0) {
            lo = upper < 0 ? upper / c0 * 1e3 : 0;
        } else if (upper < 0) {
            return null;
        }
        double lower = u - reach;
        if (c1 > 0) {
            lo = Math.max(lo, lower / c1 * 1e3);
        } else if (c1 < 0) {
            if (lower > 0) {
                return null;
            }
            hi = Math.min(hi, lower / c1 * 1e3);
        } else if (lower > 0) {
            return null;
        }
        return lo <= hi ? new double[] {lo, hi} : null;
    }

    /** The lambda (nm) with |lambda_um c - u| &lt;= reach: all of them, none (null) or an interval. */
    private static double[] axisInterval(double c, double u, double reach) {
        if (c == 0) {
            return Math.abs(u) <= reach ? new double[] {Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY} : null;
        }
        double a = (u - reach) / c * 1e3;
        double b = (u + reach) / c * 1e3;
        return new double[] {Math.min(a, b), Math.max(a, b)};
    }

    /**
     * The lobe of spread sigmaUv centred at (muU, muV), averaged over a footprint centred at (u, v): a box of
     * half-widths (hx, hy) convolved with the Gaussian g (which must be diagonal when there is a box). Peak 1 for a
     * point footprint on the lobe's centre; its integral over the (u, v) plane is pi sigmaUv^2 whatever the
     * footprint (the footprint only redistributes it).
     *
     * @param fast the shader's arithmetic: {@link ErrorFunction#fastMassInInterval}
     */
    public static double averagedLobe(double sigmaUv, double muU, double muV, double u, double v, double hx, double hy,
                               Covariance2 g, boolean fast) {
        double lobeVariance = 0.5 * sigmaUv * sigmaUv;
        if (hx == 0 && hy == 0) {
            double sxx = lobeVariance + g.xx();
            double syy = lobeVariance + g.yy();
            double sxy = g.xy();
            double det = sxx * syy - sxy * sxy;
            double du = u - muU;
            double dv = v - muV;
            double q = (syy * du * du - 2 * sxy * du * dv + sxx * dv * dv) / det;
            return sigmaUv * sigmaUv / (2 * Math.sqrt(det)) * Math.exp(-0.5 * q);
        }
        return axis(sigmaUv, lobeVariance + g.xx(), muU, u, hx, fast)
                * axis(sigmaUv, lobeVariance + g.yy(), muV, v, hy, fast);
    }

    /**
     * The box average of the lobe and its first moments about the box's centre, for a Gaussian g that is diagonal:
     * {A, average of (u' - u) lobe, average of (v' - v) lobe} into {@code out} (exact: erf and Gaussian terms).
     * The moments let a slowly varying factor (the gain C S, or W through w) enter to first order across the box.
     */
    public static void boxMoments(double sigmaUv, double muU, double muV, double u, double v, double hx, double hy,
                           Covariance2 g, double[] out) {
        double lobeVariance = 0.5 * sigmaUv * sigmaUv;
        double[] x = new double[2];
        double[] y = new double[2];
        axisMoments(sigmaUv, lobeVariance + g.xx(), muU, u, hx, x);
        axisMoments(sigmaUv, lobeVariance + g.yy(), muV, v, hy, y);
        out[0] = x[0] * y[0];
        out[1] = x[1] * y[0];
        out[2] = x[0] * y[1];
    }

    /** One axis' {average, first moment about u} of sqrt(pi) sigmaUv N(mu, variance) over [u - h, u + h]. */
    private static void axisMoments(double sigmaUv, double variance, double mu, double u, double h, double[] out) {
        double s = Math.sqrt(variance);
        double scale = SQRT_PI * sigmaUv;
        if (h == 0) {
            double d = (u - mu) / s;
            out[0] = sigmaUv / (SQRT_TWO * s) * Math.exp(-0.5 * d * d);
            out[1] = 0;
            return;
        }
        double mass = ErrorFunction.massInInterval((u - h - mu) / (SQRT_TWO * s), (u + h - mu) / (SQRT_TWO * s));
        double dLo = (u - h - mu) / s;
        double dHi = (u + h - mu) / s;
        // integral of (x - u) N(x) over the box = (mu - u) mass - s^2 (N(hi) - N(lo))
        double densityDifference = (Math.exp(-0.5 * dHi * dHi) - Math.exp(-0.5 * dLo * dLo)) / (Math.sqrt(2 * Math.PI) * s);
        out[0] = scale * mass / (2 * h);
        out[1] = scale * ((mu - u) * mass - variance * densityDifference) / (2 * h);
    }

    /** One axis: sqrt(pi) sigmaUv times the average over [u - h, u + h] of the density N(mu, variance). */
    static double axis(double sigmaUv, double variance, double mu, double u, double h, boolean fast) {
        double s = Math.sqrt(variance);
        if (h == 0) {
            double d = (u - mu) / s;
            return sigmaUv / (SQRT_TWO * s) * Math.exp(-0.5 * d * d);
        }
        double a = (u - h - mu) / (SQRT_TWO * s);
        double b = (u + h - mu) / (SQRT_TWO * s);
        // the fast erf's absolute error (1.5e-7) could make a far tail's mass slightly negative
        double mass = Math.max(0, fast ? ErrorFunction.fastMassInInterval(a, b) : ErrorFunction.massInInterval(a, b));
        return SQRT_PI * sigmaUv * mass / (2 * h);
    }
}
