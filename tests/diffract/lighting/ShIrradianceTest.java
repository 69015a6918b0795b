package diffract.lighting;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** Nine SH coefficients: exact for constant and linear environments, close to brute force for a sky. */
class ShIrradianceTest {
    @Test
    void aConstantEnvironmentGivesPiEverywhere() {
        float[] rgb = new float[3 * 128 * 64];
        java.util.Arrays.fill(rgb, 1);
        ShIrradiance sh = ShIrradiance.of(new LatLongMap(128, 64, rgb));
        for (double[] n : new double[][] {{0, 1, 0}, {1, 0, 0}, {0, -1, 0}, {0.6, 0, 0.8}}) {
            assertEquals(Math.PI, sh.irradiance(n)[1], 1e-3);
        }
    }

    @Test
    void aSkyMatchesBruteForceIrradianceWithinAFewPerCent() {
        LatLongMap sky = ClearSky.map(new double[] {0, Math.sin(Math.toRadians(50)), Math.cos(Math.toRadians(50))},
                0.25, new double[] {0.2, 0.2, 0.2}, 128, 64);
        ShIrradiance sh = ShIrradiance.of(sky);
        for (double[] n : new double[][] {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, -1, 0}}) {
            double brute = 0;
            for (int r = 0; r < sky.height(); r++) {
                for (int c = 0; c < sky.width(); c++) {
                    double[] d = sky.pixelDirection(c, r);
                    double cos = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
                    brute += sky.get(c, r, 1) * Math.max(0, cos) * sky.solidAngle(r);
                }
            }
            assertEquals(brute, sh.irradiance(n)[1], 0.06 * brute + 1e-3, "normal " + java.util.Arrays.toString(n));
        }
        // the sky on a horizontal surface: irradianceRatio, to the SH's accuracy
        assertEquals(0.25 * ClearSky.SKY_RGB[1], sh.irradiance(new double[] {0, 1, 0})[1], 0.03);
    }
}
