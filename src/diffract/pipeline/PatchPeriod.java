package diffract.pipeline;

import diffract.optics.patches.HeightField;
import diffract.optics.numerics.ShiftedDft;

import java.util.Optional;

/**
 * A patch's strongest spatial period: the peak of its height field's power spectrum away from the mean, where a
 * grating sends its first order (sin theta = lambda / d along the period's direction). Used to say which light brings
 * a patch's colour to the camera.
 *
 * @param periodUm   d, the period in micrometres
 * @param azimuthDeg the direction of the period in the patch's plane, from x towards y, in [0, 180)
 * @param powerShare the share of the spectrum's power (beside the mean) in the peak and its mirror, with their
 *                   neighbours: near 1 for a grating, small for a rough surface without a period
 */
public record PatchPeriod(double periodUm, double azimuthDeg, double powerShare) {
    /** Below this share the strongest frequency is not called the patch's period. */
    public static final double MIN_SHARE = 0.05;

    /** The strongest period of {@code field}, if one holds at least {@link #MIN_SHARE} of the power. */
    public static Optional<PatchPeriod> of(HeightField field) {
        int rows = field.rows();
        int cols = field.cols();
        if (rows < 2 || cols < 2) {
            return Optional.empty();
        }
        double mean = field.meanUm();
        double[] heights = field.heightsUm();
        double[] complex = new double[2 * rows * cols];
        for (int i = 0; i < rows * cols; i++) {
            complex[2 * i] = heights[i] - mean;
        }
        double[] spectrum = ShiftedDft.inverse(complex, rows, cols);
        int cr = rows / 2;
        int cc = cols / 2;
        double total = 0;
        double best = -1;
        int bestR = cr;
        int bestC = cc;
        double[] power = new double[rows * cols];
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                int i = r * cols + c;
                double p = spectrum[2 * i] * spectrum[2 * i] + spectrum[2 * i + 1] * spectrum[2 * i + 1];
                power[i] = p;
                if (r == cr && c == cc) {
                    continue;
                }
                total += p;
                if (p > best) {
                    best = p;
                    bestR = r;
                    bestC = c;
                }
            }
        }
        if (!(total > 0)) {
            return Optional.empty();
        }
        double peak = 0;
        for (int sign : new int[] {1, -1}) {
            int pr = cr + sign * (bestR - cr);
            int pc = cc + sign * (bestC - cc);
            for (int dr = -1; dr <= 1; dr++) {
                for (int dc = -1; dc <= 1; dc++) {
                    int r = pr + dr;
                    int c = pc + dc;
                    if (r >= 0 && r < rows && c >= 0 && c < cols && !(r == cr && c == cc)
                            && (sign == 1 || Math.abs(r - bestR) > 1 || Math.abs(c - bestC) > 1)) {
                        peak += power[r * cols + c];
                    }
                }
            }
        }
        double fx = (bestC - cc) / field.widthUm();
        double fy = (bestR - cr) / field.heightExtentUm();
        double frequency = Math.hypot(fx, fy);
        double azimuth = Math.toDegrees(Math.atan2(fy, fx));
        azimuth = ((azimuth % 180) + 180) % 180;
        double share = Math.min(1, peak / total);
        return share >= MIN_SHARE ? Optional.of(new PatchPeriod(1 / frequency, azimuth, share)) : Optional.empty();
    }
}
