package diffract.viewer;

import diffract.geometry.SnakeMesh;
import diffract.jrtr.Shape;
import diffract.jrtr.VertexAttribute;
import diffract.jrtr.VertexData;
import diffract.optics.Variant;
import diffract.scene.LightDirection;
import diffract.scene.OrbitCamera;
import diffract.scene.PrimitiveShapes;
import java.util.List;
import org.junit.jupiter.api.Test;

import java.util.concurrent.CountDownLatch;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The model, the controller's actions and the shapes, without a window. */
class ViewerModelTest {
    @Test
    void orbitCameraPutsTheEyeOnItsSphereAndClampsElevation() {
        OrbitCamera camera = OrbitCamera.facingOrigin(2);
        assertArrayEquals(new double[] {0, 0, 2}, camera.eye(), 1e-12);
        assertArrayEquals(new double[] {2, 0, 0}, camera.orbitedBy(90, 0).eye(), 1e-12);
        assertEquals(OrbitCamera.MAX_ELEVATION_DEG, camera.orbitedBy(0, 500).elevationDeg());
        assertEquals(-170, camera.orbitedBy(190, 0).azimuthDeg(), 1e-12);
        assertEquals(OrbitCamera.MIN_DISTANCE, camera.zoomedBy(1e-6).distance());
    }

    @Test
    void lightStaysAboveTheHorizon() {
        LightDirection light = new LightDirection(80, 350);
        assertEquals(LightDirection.MAX_THETA_DEG, light.movedBy(20, 0).thetaDeg());
        assertEquals(0, light.movedBy(-100, 0).thetaDeg());
        assertEquals(-10, light.phiDeg(), 1e-12);
    }

    @Test
    void keysChangeTheModelAndOnlyNeededTermsArePrecomputed() throws InterruptedException {
        CountDownLatch precomputeMayFinish = new CountDownLatch(1);
        ViewerModel model = ViewerTestSupport.model(ViewerTestSupport.gatedTerms(precomputeMayFinish));
        try (TermPrecomputer precomputer = new TermPrecomputer(model)) {
            boolean[] quit = {false};
            ViewerController controller = new ViewerController(model, precomputer, () -> null, () -> quit[0] = true);
            controller.handleKey((short) 0, '2');
            assertEquals(Variant.NMM, model.state().settings().variant());
            controller.handleKey((short) 0, ']');
            assertEquals(40, model.state().settings().spectral().lambdaStepNm());
            controller.handleKey((short) 0, '[');
            controller.handleKey((short) 0, '[');
            assertEquals(10, model.state().settings().spectral().lambdaStepNm());
            controller.handleKey((short) 0, '-');
            assertEquals(7, model.state().settings().taylor().highestOrder());
            assertTrue(!precomputer.isBusy(), "fewer terms need no precompute");
            controller.handleKey((short) 0, '+');
            controller.handleKey((short) 0, '+');
            controller.handleKey((short) 0, '+');
            assertEquals(10, model.state().settings().taylor().highestOrder());
            assertTrue(precomputer.isBusy(), "more terms than at hand start a precompute");
            assertEquals(8, model.state().drawableSettings().taylor().highestOrder(), "draws with the terms at hand meanwhile");
            precomputeMayFinish.countDown();
            assertTrue(ViewerTestSupport.waitFor(() -> model.state().terms().highestOrder() == 10, 30));
            assertTrue(ViewerTestSupport.waitFor(() -> model.state().precompute() == null && !precomputer.isBusy(), 5));
            assertEquals(10, model.state().drawableSettings().taylor().highestOrder());
            controller.handleKey(com.jogamp.newt.event.KeyEvent.VK_UP, '\0');
            assertEquals(25, model.state().view().light().thetaDeg(), 1e-12);
            controller.handleKey((short) 0, 'p');
            assertTrue(model.state().notice().text().contains("no pigmentation image"));
            controller.handleKey((short) 0, 'r');
            assertEquals(Variant.FLSS, model.state().settings().variant());
            assertEquals(8, model.state().settings().taylor().highestOrder());
            assertEquals(10, model.state().terms().highestOrder(), "reset keeps the precomputed terms");
            assertEquals(30, model.state().view().light().thetaDeg(), 1e-12);
            controller.handleKey((short) 0, 'q');
            assertTrue(quit[0]);
            assertNull(model.state().precompute());
        }
    }

    @Test
    void titleNamesVariantParametersAndProgress() {
        ViewerModel model = ViewerTestSupport.model(ViewerTestSupport.directTerms());
        ViewerState state = model.update(s -> s.withSettings(s.settings().with(b -> b.highestOrder(12)))
                .withPrecompute(new PrecomputeProgress(12, 0.4)));
        String title = ViewerTitle.of(model, state, new FrameStats(), System.nanoTime());
        assertEquals("diffract test-patch | flss N=8 dlambda=20 nm R=1 | theta_i 30 phi_i 90 | sphere | exposure 10"
                + " | - ms/frame | precomputing N=12 40%", title);
    }

    @Test
    void shapesCarryUnitTangentsPerpendicularToTheirNormals() {
        double[] x = {1, 0, 0};
        for (Shape shape : List.of(PrimitiveShapes.sphere(x), PrimitiveShapes.plane(x), PrimitiveShapes.cylinder(x),
                PrimitiveShapes.snake(SnakeMesh.Parameters.defaults()))) {
            String kind = shape.name();
            VertexData data = shape.vertexData();
            float[] n = data.attribute(VertexAttribute.NORMAL);
            float[] t = data.attribute(VertexAttribute.TANGENT);
            for (int v = 0; v < data.vertexCount(); v++) {
                double dot = n[3 * v] * t[3 * v] + n[3 * v + 1] * t[3 * v + 1] + n[3 * v + 2] * t[3 * v + 2];
                double length = Math.sqrt(t[3 * v] * t[3 * v] + t[3 * v + 1] * t[3 * v + 1] + t[3 * v + 2] * t[3 * v + 2]);
                assertEquals(0, dot, 1e-5, kind + " vertex " + v);
                assertEquals(1, length, 1e-5, kind + " vertex " + v);
            }
        }
        // on the plane the patch's x axis follows the requested direction, projected into the plane
        float[] t = PrimitiveShapes.plane(new double[] {1, 1, 5}).vertexData().attribute(VertexAttribute.TANGENT);
        assertArrayEquals(new float[] {(float) Math.sqrt(0.5), (float) Math.sqrt(0.5), 0}, new float[] {t[0], t[1], t[2]},
                1e-6f);
    }
}
