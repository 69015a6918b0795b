package diffract.app;

import diffract.pipeline.PatchPeriod;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The light a dark still's notice names sends the patch's first order at 550 nm to the camera (the grating equation
 * on the plane), and the probe's bright pixels are its lit pixels' 99th percentile.
 */
class DarkStillNoticeTest {
    @Test
    void theNamedLightSendsTheFirstOrderToACameraOverhead() {
        PatchPeriod ridges = new PatchPeriod(1.1, 90, 1);
        double[] light = DarkStillNotice.firstOrderLight(ridges, new double[] {0, 0, 3}, new double[3]).orElseThrow();
        assertEquals(Math.toDegrees(Math.asin(0.55 / 1.1)), light[0], 1e-9);
        assertEquals(90, Math.abs(light[1] - 180), 1e-9, "in the plane of the period: phi 90 or 270");
        // a tilted camera: omega_i.xy + omega_r.xy = -lambda f for the order sent to it
        double[] eye = {0, Math.sin(Math.toRadians(20)), Math.cos(Math.toRadians(20))};
        double[] tilted = DarkStillNotice.firstOrderLight(ridges, eye, new double[3]).orElseThrow();
        double wiY = Math.sin(Math.toRadians(tilted[0])) * Math.sin(Math.toRadians(tilted[1]));
        assertEquals(0.5, Math.abs(wiY + eye[1]), 1e-9);
    }

    @Test
    void aPeriodBelowHalfTheWavelengthSendsNoOrderAnywhere() {
        assertTrue(DarkStillNotice.firstOrderLight(new PatchPeriod(0.25, 0, 1), new double[] {0, 0, 3},
                new double[3]).isEmpty());
    }

    @Test
    void theBrightPixelsAreTheLitOnesNinetyNinthPercentile() {
        int n = 1000;
        float[] rgb = new float[3 * (n + 10)];
        float[] mask = new float[rgb.length];
        for (int p = 0; p < n; p++) {
            java.util.Arrays.fill(rgb, 3 * p, 3 * p + 3, (p + 1) / 1000f); // Y = (p + 1) / 1000 on the shape
            java.util.Arrays.fill(mask, 3 * p, 3 * p + 3, 1f);
        }
        for (int p = n; p < n + 10; p++) {
            java.util.Arrays.fill(rgb, 3 * p, 3 * p + 3, 50f); // off the shape: not counted
        }
        StructuralProbe probe = StructuralProbe.of(rgb, mask, 2);
        assertEquals(n, probe.shapePixels());
        assertEquals(0.5, probe.brightestY(), 1e-6, "per unit of exposure");
        assertEquals(0.991 / 2, probe.brightY(), 1e-6);
        assertEquals(2 / 0.991, probe.autoExposure(1), 1e-4);
    }
}
