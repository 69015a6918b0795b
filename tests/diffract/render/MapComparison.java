package diffract.render;

import diffract.app.AutoExposure;
import diffract.colour.Ciede2000;
import diffract.colour.D65;
import diffract.colour.Lab;
import diffract.colour.Xyz;
import diffract.optics.Direction;

import java.util.Arrays;

/**
 * CIEDE2000 statistics between two XYZ BRDF maps seen through one exposure: both maps are multiplied by the same
 * exposure (chosen from the first map, the CPU's, as {@link AutoExposure} would: its brightest diffracted pixel
 * maps to Y = 1), then converted to L*a*b* with the D65 white, pixel by pixel inside the unit disk.
 */
record MapComparison(double exposure, double mean, double p95, double p99, double max, int pixels, int lit) {
    /** A pixel counts as lit when its exposed Y exceeds 1 % of white (L* above 9). */
    static final double LIT_Y = 0.01;

    static MapComparison of(float[] cpuXyz, float[] gpuXyz, int size, Direction wi) {
        float[] luminance = new float[size * size];
        for (int p = 0; p < luminance.length; p++) {
            luminance[p] = cpuXyz[3 * p + 1];
        }
        return of(cpuXyz, gpuXyz, size, AutoExposure.of(luminance, size, -wi.x(), -wi.y()));
    }

    static MapComparison of(float[] aXyz, float[] bXyz, int size, double exposure) {
        Xyz white = D65.whiteXyz();
        double[] delta = new double[size * size];
        int n = 0;
        int lit = 0;
        for (int j = 0; j < size; j++) {
            for (int i = 0; i < size; i++) {
                double x = 2.0 * (i + 0.5) / size - 1;
                double y = 1 - 2.0 * (j + 0.5) / size;
                if (x * x + y * y >= 1) {
                    continue;
                }
                int p = 3 * (j * size + i);
                Lab a = Lab.fromXyz(new Xyz(aXyz[p], aXyz[p + 1], aXyz[p + 2]).scaled(exposure), white);
                Lab b = Lab.fromXyz(new Xyz(bXyz[p], bXyz[p + 1], bXyz[p + 2]).scaled(exposure), white);
                delta[n++] = Ciede2000.deltaE(a, b);
                lit += aXyz[p + 1] * exposure > LIT_Y ? 1 : 0;
            }
        }
        double[] d = Arrays.copyOf(delta, n);
        Arrays.sort(d);
        double sum = 0;
        for (double v : d) {
            sum += v;
        }
        return new MapComparison(exposure, sum / n, percentile(d, 0.95), percentile(d, 0.99), d[n - 1], n, lit);
    }

    /** The value below which the fraction q of the sorted values lies (nearest rank). */
    static double percentile(double[] sorted, double q) {
        int rank = (int) Math.ceil(q * sorted.length) - 1;
        return sorted[Math.max(0, Math.min(sorted.length - 1, rank))];
    }

    @Override
    public String toString() {
        return String.format(java.util.Locale.ROOT, "exposure %.4g: CIEDE2000 mean %.4f, p95 %.4f, p99 %.4f, max %.3f over %d px (%d lit)",
                exposure, mean, p95, p99, max, pixels, lit);
    }
}
