package diffract.optics;

import diffract.optics.patches.HeightField;

/**
 * A scan as wide as the coherence window, for the tests of the averaged window on the CPU and the GPU: a ridge along
 * y whose period does not divide the scan (its orders spread over neighbouring texels, as a real scan's do), a weaker
 * cross ridge, and a smooth random relief whose edges do not match (the DFT's periodic patch has a seam).
 */
public final class WideScan {
    /** The ridge's period: 33.1 periods on a 48 um scan. */
    public static final double RIDGE_UM = 1.45;

    private WideScan() {
    }

    /** {@code samples} x {@code samples} heights {@code pixelUm} apart, mean-subtracted (max |h| about 0.11 um). */
    public static HeightField of(int samples, double pixelUm) {
        java.util.Random random = new java.util.Random(7);
        int waves = 12;
        double[] kx = new double[waves];
        double[] ky = new double[waves];
        double[] phase = new double[waves];
        for (int j = 0; j < waves; j++) {
            kx[j] = 2 * Math.PI * (random.nextDouble() - 0.5) * 0.6;
            ky[j] = 2 * Math.PI * (random.nextDouble() - 0.5) * 0.6;
            phase[j] = 2 * Math.PI * random.nextDouble();
        }
        double[] h = new double[samples * samples];
        for (int r = 0; r < samples; r++) {
            for (int c = 0; c < samples; c++) {
                double x = c * pixelUm;
                double y = r * pixelUm;
                double z = 0.08 * Math.sin(2 * Math.PI * y / RIDGE_UM) + 0.02 * Math.sin(2 * Math.PI * x / 2.4 + 0.3);
                for (int j = 0; j < waves; j++) {
                    z += 0.006 * Math.cos(kx[j] * x + ky[j] * y + phase[j]);
                }
                h[r * samples + c] = z;
            }
        }
        return HeightField.of(samples, samples, h, pixelUm).meanSubtracted();
    }
}
