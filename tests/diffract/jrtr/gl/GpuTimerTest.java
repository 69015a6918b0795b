package diffract.jrtr.gl;

import diffract.jrtr.GlTestSupport;
import diffract.jrtr.OffscreenTarget;
import diffract.jrtr.Renderer;
import diffract.jrtr.scenegraph.Group;
import diffract.jrtr.scenegraph.ShapeNode;
import diffract.jrtr.scenegraph.Shapes;
import diffract.util.TestReport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

@Tag("gl")
class GpuTimerTest {
    @Test
    void medianFrameTimeIsPositiveAndFinite() {
        GlTestSupport.assumeOffscreenGl();
        Group root = new Group("root").add(new ShapeNode(Shapes.cube(0.5f), GlTestSupport.unlit(1, 0, 0)));
        try (OffscreenTarget target = new OffscreenTarget(new Renderer(root, GlTestSupport.unitCamera(),
                GlTestSupport.rightAngleFrustum()))) {
            double ms = target.measureMedianMs(128, 128, 3, 10);
            TestReport.line(GpuTimerTest.class, "GpuTimer: median " + ms + " ms per 128x128 frame on " + target.info().renderer());
            assertTrue(ms > 0 && Double.isFinite(ms), "median " + ms);
            assertTrue(ms < 10_000, "a tiny frame should not take seconds: " + ms);
            assertThrows(IllegalArgumentException.class, () -> target.withContext(gl ->
                    new GpuTimer(gl).measureMedianMs(() -> { }, 0, 9)));
        }
    }

    @Test
    void medianOfOddAndEvenCounts() {
        assertEquals(2.0, GpuTimer.median(new double[] {3, 1, 2}));
        assertEquals(2.5, GpuTimer.median(new double[] {4, 1, 3, 2}));
    }
}
