package diffract.colour;

import java.util.Arrays;

/**
 * CIEDE2000 differences between two images of CIE XYZ values (relative to D65 white, Y = 1), summarised as mean
 * and percentiles: how the project states the error of an approximation against the exact reference.
 */
public record DeltaEStatistics(int pixels, double mean, double p95, double p99, double max) {

    /**
     * @param xyzA      3 floats per pixel
     * @param xyzB      3 floats per pixel, same size
     * @param include   which pixels count (null: all)
     */
    public static DeltaEStatistics of(float[] xyzA, float[] xyzB, boolean[] include) {
        if (xyzA.length != xyzB.length || xyzA.length % 3 != 0) {
            throw new IllegalArgumentException("images differ in size: " + xyzA.length + " vs " + xyzB.length + " floats");
        }
        Xyz white = D65.whiteXyz();
        double[] differences = new double[xyzA.length / 3];
        int n = 0;
        for (int p = 0; p < differences.length; p++) {
            if (include != null && !include[p]) {
                continue;
            }
            Lab a = Lab.fromXyz(new Xyz(xyzA[3 * p], xyzA[3 * p + 1], xyzA[3 * p + 2]), white);
            Lab b = Lab.fromXyz(new Xyz(xyzB[3 * p], xyzB[3 * p + 1], xyzB[3 * p + 2]), white);
            differences[n++] = Ciede2000.deltaE(a, b);
        }
        if (n == 0) {
            throw new IllegalArgumentException("no pixels to compare");
        }
        double[] sorted = Arrays.copyOf(differences, n);
        Arrays.sort(sorted);
        double sum = 0;
        for (double d : sorted) {
            sum += d;
        }
        return new DeltaEStatistics(n, sum / n, percentile(sorted, 0.95), percentile(sorted, 0.99), sorted[n - 1]);
    }

    /** Nearest-rank percentile of sorted values. */
    static double percentile(double[] sorted, double q) {
        int rank = (int) Math.ceil(q * sorted.length);
        return sorted[Math.max(0, Math.min(sorted.length - 1, rank - 1))];
    }
}
