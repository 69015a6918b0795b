package diffract.optics.spectra;

/** The Taylor weights (k w)^n / n! of 004 eq. {@code finalexpression}, by recurrence so n! never overflows. */
final class TaylorCoefficients {
    private TaylorCoefficients() {
    }

    /** c_0 = 1, c_n = c_{n-1} * a / n, for a = k w. */
    static double[] of(double a, int highestOrder) {
        double[] c = new double[highestOrder + 1];
        c[0] = 1.0;
        for (int n = 1; n <= highestOrder; n++) {
            c[n] = c[n - 1] * a / n;
        }
        return c;
    }
}
