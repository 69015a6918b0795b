package diffract.optics;

import diffract.optics.numerics.ShiftedDft;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.windows.CoherenceWindow;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

import java.util.Locale;

/**
 * The measurements of docs/measurements/scans.md, "How wide a scan must be" (not a test: it asserts nothing and runs only with
 * {@code -Ddiffract.measure=scans}). How well does a scan of width L estimate the BRDF of the skin it was cut from,
 * at the thesis' 65 um coherence, with the window averaged over its position, fixed at the DFT's origin, and averaged
 * over a Tukey-tapered scan (the apodisation against the leakage of the scan's non-matching edges)?
 *
 * <p>The skin: the Elaphe-like relief over 2304 x 2304 samples of 0.0993 um (229 um, 200 ridges), whose averaged
 * BRDF, 3.5 coherence lengths wide, is the yardstick. Scans of 256 to 2048 samples are cut out of it at an arbitrary
 * place. Monochromatic (550 nm, w = -1.8, the first orders and the mirror), each map averaged over the pixels of a
 * 64 x 64 BRDF map; errors as the L1 difference over the map (of the yardstick's total) and the mean relative
 * difference over the lit pixels (above 1 % of the yardstick's peak).
 *
 * <pre>mvn -q test -Dtest=ScanSizeMeasurement -Ddiffract.measure=scans</pre>
 */
class ScanSizeMeasurement {
    static final double LAMBDA_UM = 0.55;
    static final double PHASE_PER_UM = 2 * Math.PI / LAMBDA_UM * -1.8;
    static final double STEP = 0.002; // cycles per um between map samples
    static final double[] FX = range(-0.4, 0.4);
    static final double[] FY = range(-0.3, 1.3);
    static final double SIGMA_F = CoherenceWindow.thesis().sigmaFrequencyPerUm();

    @Test
    void measure() {
        Assumptions.assumeTrue("scans".equals(System.getProperty("diffract.measure")), "measurement only on request");
        HeightField skin = SyntheticPatches.elapheLike(2304, 200, SyntheticPatches.ELAPHE_RIDGE_PERIOD_UM, 0.3, 1L)
                .meanSubtracted();
        double[][] truth = pixels(map(skin, 0, 0, skin.rows(), null, true));
        System.out.println("| scan | width | sigma_f | averaged | averaged, Tukey 0.25 taper | fixed |");
        System.out.println("|---|---|---|---|---|---|");
        for (int n : new int[] {256, 512, 1024, 2048}) {
            double[][] averaged = pixels(map(skin, 100, 200, n, null, true));
            double[][] tapered = pixels(map(skin, 100, 200, n, tukey(n, 0.25), true));
            double[][] fixed = pixels(map(skin, 100, 200, n, null, false));
            double widthUm = n * skin.pixelSizeXUm();
            System.out.printf(Locale.ROOT, "| %d x %d | %.0f um | %.2f texels | %s | %s | %s |%n", n, n, widthUm,
                    SIGMA_F * widthUm, error(averaged, truth), error(tapered, truth), error(fixed, truth));
        }
    }

    static double[] range(double from, double to) {
        int n = (int) Math.round((to - from) / STEP) + 1;
        double[] out = new double[n];
        for (int i = 0; i < n; i++) {
            out[i] = from + i * STEP;
        }
        return out;
    }

    /** Tukey window of n samples, cosine edges over alpha / 2 of each end. */
    static double[] tukey(int n, double alpha) {
        double[] t = new double[n];
        for (int i = 0; i < n; i++) {
            double x = i / (n - 1.0);
            t[i] = x < alpha / 2 ? 0.5 * (1 - Math.cos(2 * Math.PI * x / alpha))
                    : x > 1 - alpha / 2 ? 0.5 * (1 - Math.cos(2 * Math.PI * (1 - x) / alpha)) : 1;
        }
        return t;
    }

    /**
     * |P|^2 on the (FY, FX) grid of the n x n scan cut at (row0, col0): averaged, sum_m |T_m|^2 G(s - m)^2, or fixed,
     * |sum_m T_m G(s - m)|^2, with T = fftshift(ifft2(taper exp(i a h))) / rms(taper).
     */
    static double[][] map(HeightField skin, int row0, int col0, int n, double[] taper, boolean averaged) {
        double[] e = new double[2 * n * n];
        double mean = 0;
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                mean += skin.heightUm(row0 + r, col0 + c) / ((double) n * n);
            }
        }
        double norm = 0;
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                double w = taper == null ? 1 : taper[r] * taper[c];
                norm += w * w / ((double) n * n);
                double phase = PHASE_PER_UM * (skin.heightUm(row0 + r, col0 + c) - mean);
                e[2 * (r * n + c)] = w * Math.cos(phase);
                e[2 * (r * n + c) + 1] = w * Math.sin(phase);
            }
        }
        double[] t = ShiftedDft.inverse(e, n, n);
        double scale = 1 / Math.sqrt(norm);
        double sigmaTexels = SIGMA_F * n * skin.pixelSizeXUm();
        double extentUm = n * skin.pixelSizeXUm();
        double[][] gx = window(FX, extentUm, n, sigmaTexels, averaged);
        double[][] gy = window(FY, extentUm, n, sigmaTexels, averaged);
        double[][] out = new double[FY.length][FX.length];
        // separable: first along x for every row of texels, then along y
        double[][] re = new double[n][FX.length];
        double[][] im = new double[n][FX.length];
        int[] xs = texels(FX, extentUm, n, sigmaTexels);
        int[] ys = texels(FY, extentUm, n, sigmaTexels);
        for (int my = ys[0]; my <= ys[1]; my++) {
            for (int mx = xs[0]; mx <= xs[1]; mx++) {
                int i = 2 * (my * n + mx);
                double a = t[i] * scale;
                double b = t[i + 1] * scale;
                double power = a * a + b * b;
                for (int j = 0; j < FX.length; j++) {
                    double g = gx[j][mx];
                    if (g == 0) {
                        continue;
                    }
                    if (averaged) {
                        re[my][j] += g * power;
                    } else {
                        re[my][j] += g * a;
                        im[my][j] += g * b;
                    }
                }
            }
        }
        for (int k = 0; k < FY.length; k++) {
            for (int j = 0; j < FX.length; j++) {
                double a = 0;
                double b = 0;
                for (int my = ys[0]; my <= ys[1]; my++) {
                    double g = gy[k][my];
                    if (g != 0) {
                        a += g * re[my][j];
                        b += g * im[my][j];
                    }
                }
                out[k][j] = averaged ? a : a * a + b * b;
            }
        }
        return out;
    }

    /** The texel indices (array positions) whose window reaches the map's frequencies: {first, last}. */
    static int[] texels(double[] f, double extentUm, int n, double sigmaTexels) {
        int lo = (int) Math.floor(f[0] * extentUm - 8 * sigmaTexels) + n / 2;
        int hi = (int) Math.ceil(f[f.length - 1] * extentUm + 8 * sigmaTexels) + n / 2;
        return new int[] {Math.max(0, lo), Math.min(n - 1, hi)};
    }

    /** G(s - m) (fixed) or G(s - m)^2 (averaged) for every map frequency and texel, 0 beyond 8 sigma. */
    static double[][] window(double[] f, double extentUm, int n, double sigmaTexels, boolean squared) {
        double[][] g = new double[f.length][n];
        for (int j = 0; j < f.length; j++) {
            double s = f[j] * extentUm;
            for (int m = 0; m < n; m++) {
                double d = (s - (m - n / 2)) / sigmaTexels;
                if (Math.abs(d) < 8) {
                    double w = Math.exp(-0.5 * d * d);
                    g[j][m] = squared ? w * w : w;
                }
            }
        }
        return g;
    }

    /** The map averaged over the pixels of a 64 x 64 BRDF map (2 / 64 in u, 2 / 64 / lambda in frequency). */
    static double[][] pixels(double[][] map) {
        int k = (int) Math.round(2.0 / 64 / LAMBDA_UM / STEP);
        int rows = map.length / k;
        int cols = map[0].length / k;
        double[][] out = new double[rows][cols];
        for (int r = 0; r < rows * k; r++) {
            for (int c = 0; c < cols * k; c++) {
                out[r / k][c / k] += map[r][c] / (k * k);
            }
        }
        return out;
    }

    /** "L1 / lit mean" of a map against the yardstick. */
    static String error(double[][] map, double[][] truth) {
        double total = 0;
        double l1 = 0;
        double peak = 0;
        for (double[] row : truth) {
            for (double v : row) {
                peak = Math.max(peak, v);
            }
        }
        double lit = 0;
        int litPixels = 0;
        for (int r = 0; r < truth.length; r++) {
            for (int c = 0; c < truth[r].length; c++) {
                double d = Math.abs(map[r][c] - truth[r][c]);
                total += truth[r][c];
                l1 += d;
                if (truth[r][c] > 0.01 * peak) {
                    lit += d / truth[r][c];
                    litPixels++;
                }
            }
        }
        return String.format(Locale.ROOT, "%.3f / %.3f", l1 / total, lit / litPixels);
    }
}
