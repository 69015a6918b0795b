package diffract.precompute;

import diffract.util.Reporter;

import java.nio.file.Path;
import java.util.Locale;

/**
 * max|h| of a patch known only through its Taylor terms (a thesis folder from the original script).
 *
 * <p>At zero frequency, term n is ifft2((i h)^n)(0) = i^n mean(h^n). For even n this gives the moment
 * M_n = mean(h^n)^(1/n), and for R x C samples M_n <= max|h| <= M_n (R C)^(1/n): the lower bound because no
 * sample exceeds the maximum, the upper because the largest sample alone contributes max|h|^n / (R C) to the
 * mean. Both tighten as n grows (for N = 30 and 256 x 256 samples the bracket is a factor 1.45 wide). We use the
 * smallest upper bound over the even terms at hand: it is never below the truth, so a Taylor remainder bound
 * computed from it stays safe. With term 1 only, Parseval gives M_2 (the RMS height) as the sum of |term 1|^2.
 *
 * @param lowerUm the largest lower bound found
 * @param upperUm the smallest upper bound found (the estimate used)
 * @param order   the order n of the upper bound, 0 when there was nothing to estimate from (term 0 only)
 */
record MaxHeightEstimate(double lowerUm, double upperUm, int order) {

    /** From our-layout terms (zero frequency at the centre texel), in micrometres. */
    static MaxHeightEstimate fromMoments(float[][] terms, int rows, int cols) {
        int centre = 2 * ((rows / 2) * cols + cols / 2);
        double samples = (double) rows * cols;
        double lower = 0;
        double upper = Double.POSITIVE_INFINITY;
        int order = 0;
        if (terms.length == 2) {
            double meanSquare = 0;
            for (float v : terms[1]) {
                meanSquare += (double) v * v;
            }
            lower = Math.sqrt(meanSquare);
            upper = lower * Math.sqrt(samples);
            order = 2;
        }
        for (int n = 2; n < terms.length; n += 2) {
            double moment = Math.abs((double) terms[n][centre]); // Re; Im is i^n's zero imaginary part
            if (!(moment > 0) || !Double.isFinite(moment)) {
                continue; // underflowed or flat: no information
            }
            double m = Math.pow(moment, 1.0 / n);
            lower = Math.max(lower, m);
            double u = m * Math.pow(samples, 1.0 / n);
            if (u < upper) {
                upper = u;
                order = n;
            }
        }
        if (order == 0) {
            return new MaxHeightEstimate(0, 0, 0);
        }
        return new MaxHeightEstimate(lower, upper, order);
    }

    /** Says in one line what was estimated and returns the value to use. */
    double reportTo(Reporter reporter, Path dir) {
        if (order == 0) {
            reporter.info(dir + ": max|h| unknown (no term of order >= 1 to estimate it from); using 0");
            return 0;
        }
        reporter.info(String.format(Locale.ROOT, "%s: max|h| not stored; from the zero-frequency moments "
                + "mean(h^n)^(1/n) it lies in [%.4g, %.4g] um; using %.4g um (the upper bound, from n = %d)",
                dir, lowerUm, upperUm, upperUm, order));
        return upperUm;
    }
}
