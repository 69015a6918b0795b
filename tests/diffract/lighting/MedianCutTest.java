package diffract.lighting;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Median cut (Debevec 2005): energy kept exactly, a bright pixel becomes a light in its direction, equal shares. */
class MedianCutTest {
    static LatLongMap uniform(int w, int h, float value) {
        float[] rgb = new float[3 * w * h];
        java.util.Arrays.fill(rgb, value);
        return new LatLongMap(w, h, rgb);
    }

    @Test
    void pixelsCoverTheSphereAndTheLightsCarryTheMapsPowerExactly() {
        LatLongMap sky = ClearSky.map(new double[] {0.3, 0.8, Math.sqrt(1 - 0.73)}, 0.25, new double[] {0.2, 0.18, 0.15},
                128, 64);
        double sphere = 0;
        for (int r = 0; r < 64; r++) {
            sphere += 128 * sky.solidAngle(r);
        }
        assertEquals(4 * Math.PI, sphere, 1e-9);
        double[] total = sky.totalPower();
        for (int rounds = 0; rounds <= 5; rounds++) {
            List<ExtendedLight> lights = MedianCut.lights(sky, rounds);
            assertEquals(1 << rounds, lights.size());
            double[] sum = new double[3];
            double solidAngle = 0;
            for (ExtendedLight l : lights) {
                for (int k = 0; k < 3; k++) {
                    sum[k] += l.rgb()[k];
                }
                solidAngle += l.solidAngleSr();
                assertEquals(1, Math.sqrt(l.direction()[0] * l.direction()[0] + l.direction()[1] * l.direction()[1]
                        + l.direction()[2] * l.direction()[2]), 1e-12);
            }
            for (int k = 0; k < 3; k++) {
                assertEquals(total[k], sum[k], 1e-9 * total[k]);
            }
            assertEquals(4 * Math.PI, solidAngle, 1e-9);
        }
    }

    @Test
    void aSingleBrightPixelBecomesALightInItsDirectionCarryingItsPower() {
        LatLongMap dim = uniform(64, 32, 0.001f);
        float[] rgb = dim.rgb();
        int column = 40;
        int row = 9;
        for (int k = 0; k < 3; k++) {
            rgb[3 * (row * 64 + column) + k] = 5000;
        }
        LatLongMap map = new LatLongMap(64, 32, rgb);
        List<ExtendedLight> lights = MedianCut.lights(map, 4);
        ExtendedLight brightest = lights.get(0);
        double[] expected = map.pixelDirection(column, row);
        double cos = brightest.direction()[0] * expected[0] + brightest.direction()[1] * expected[1]
                + brightest.direction()[2] * expected[2];
        assertTrue(cos > Math.cos(Math.toRadians(0.5)), "the light is " + Math.toDegrees(Math.acos(cos))
                + " degrees from the bright pixel");
        double pixelPower = 5000 * map.solidAngle(row);
        assertTrue(brightest.rgb()[1] >= pixelPower && brightest.rgb()[1] < pixelPower * 1.01,
                "power " + brightest.rgb()[1] + " vs the pixel's " + pixelPower);
    }

    @Test
    void aUniformMapSplitsIntoEqualShares() {
        LatLongMap map = uniform(256, 128, 1);
        List<ExtendedLight> lights = MedianCut.lights(map, 3);
        for (ExtendedLight l : lights) {
            // 4 pi / 8 each, to within a pixel row's share
            assertEquals(4 * Math.PI / 8, l.rgb()[0], 0.04 * 4 * Math.PI / 8);
            assertEquals(l.rgb()[0], l.solidAngleSr(), 1e-9);
            assertTrue(l.angularDiameterDeg() > 60 && l.angularDiameterDeg() < 90, "diameter " + l.angularDiameterDeg());
        }
    }

    @Test
    void angularDiameterOfTheSunsSolidAngle() {
        // the sun: 0.53 degrees across, 6.8e-5 sr
        double omega = 2 * Math.PI * (1 - Math.cos(Math.toRadians(0.53 / 2)));
        assertEquals(0.53, ExtendedLight.of(new double[] {0, 1, 0}, new double[3], omega).angularDiameterDeg(), 1e-9);
    }
}
