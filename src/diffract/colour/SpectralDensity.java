package diffract.colour;

/**
 * The tristimulus density of D65 light seen by the CIE 1931 observer over a wavelength band, normalised to a white
 * of unit luminance: f(lambda) = S(lambda) (xbar, ybar, zbar)(lambda) / N with N = integral over the band of
 * S ybar, so that XYZ = integral of f(lambda) r(lambda) d lambda is exactly D65 white with Y = 1 for r = 1. S and the
 * CMFs are interpolated linearly between their 1 nm nodes ({@link D65}, {@link Cie1931}), so f is a quadratic between
 * whole nanometres and N is integrated exactly (Simpson's rule per nanometre). This is the continuous integral that
 * {@link SpectralIntegrator}'s quadratures approximate; the filtered reference integrates against it directly.
 * With {@link MirrorNormalisation#ENERGY} f carries the mirror's factor (lambda_0 / lambda)^2 (N does not).
 */
public final class SpectralDensity {
    private final double lambdaMinNm;
    private final double lambdaMaxNm;
    private final double normaliser;
    private final MirrorNormalisation normalisation;

    /** The thesis' weighting ({@link MirrorNormalisation#PEAK}). */
    public SpectralDensity(double lambdaMinNm, double lambdaMaxNm) {
        this(lambdaMinNm, lambdaMaxNm, MirrorNormalisation.PEAK);
    }

    public SpectralDensity(double lambdaMinNm, double lambdaMaxNm, MirrorNormalisation normalisation) {
        this.normalisation = normalisation;
        if (!(lambdaMinNm > 0) || !(lambdaMaxNm > lambdaMinNm)) {
            throw new IllegalArgumentException("need 0 < lambda_min < lambda_max, got " + lambdaMinNm + ", " + lambdaMaxNm);
        }
        this.lambdaMinNm = lambdaMinNm;
        this.lambdaMaxNm = lambdaMaxNm;
        double n = 0;
        double lo = lambdaMinNm;
        while (lo < lambdaMaxNm) {
            double hi = Math.min(lambdaMaxNm, Math.floor(lo) + 1.0);
            double mid = 0.5 * (lo + hi);
            n += (hi - lo) / 6.0 * (luminance(lo) + 4 * luminance(mid) + luminance(hi));
            lo = hi;
        }
        if (!(n > 0)) {
            throw new IllegalArgumentException("the band " + lambdaMinNm + ".." + lambdaMaxNm
                    + " nm sees no D65 luminance");
        }
        this.normaliser = n;
    }

    private static double luminance(double lambdaNm) {
        return D65.relativePower(lambdaNm) * Cie1931.yBar(lambdaNm);
    }

    /** f(lambda) = S (xbar, ybar, zbar) / N into {@code out}; 0 outside the band. */
    public void at(double lambdaNm, double[] out) {
        if (lambdaNm < lambdaMinNm || lambdaNm > lambdaMaxNm) {
            out[0] = 0;
            out[1] = 0;
            out[2] = 0;
            return;
        }
        double s = D65.relativePower(lambdaNm) * normalisation.factor(lambdaNm) / normaliser;
        out[0] = s * Cie1931.xBar(lambdaNm);
        out[1] = s * Cie1931.yBar(lambdaNm);
        out[2] = s * Cie1931.zBar(lambdaNm);
    }

    /** N = integral over the band of S ybar (S relative to 100 at 560 nm). */
    public double normaliser() {
        return normaliser;
    }

    public double lambdaMinNm() {
        return lambdaMinNm;
    }

    public double lambdaMaxNm() {
        return lambdaMaxNm;
    }
}
