package diffract.viewer;

import diffract.geometry.SnakeMesh;
import diffract.jrtr.scenegraph.Shape;
import diffract.jrtr.scenegraph.VertexAttribute;
import diffract.jrtr.scenegraph.VertexData;
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
            press(controller, (short) 0, '2');
            assertEquals(Variant.NMM, model.state().settings().variant());
            press(controller, (short) 0, ']');
            assertEquals(40, model.state().settings().spectral().lambdaStepNm());
            press(controller, (short) 0, '[');
            press(controller, (short) 0, '[');
            assertEquals(10, model.state().settings().spectral().lambdaStepNm());
            press(controller, (short) 0, '-');
            assertEquals(7, model.state().settings().taylor().highestOrder());
            assertTrue(!precomputer.isBusy(), "fewer terms need no precompute");
            press(controller, (short) 0, '+');
            press(controller, (short) 0, '+');
            press(controller, (short) 0, '+');
            assertEquals(10, model.state().settings().taylor().highestOrder());
            assertTrue(precomputer.isBusy(), "more terms than at hand start a precompute");
            assertEquals(8, model.state().drawableSettings().taylor().highestOrder(), "draws with the terms at hand meanwhile");
            precomputeMayFinish.countDown();
            assertTrue(ViewerTestSupport.waitFor(() -> model.state().terms().highestOrder() == 10, 300));
            assertTrue(ViewerTestSupport.waitFor(() -> model.state().precompute() == null && !precomputer.isBusy(), 300));
            assertEquals(10, model.state().drawableSettings().taylor().highestOrder());
            press(controller, com.jogamp.newt.event.KeyEvent.VK_UP, '\0');
            assertEquals(25, model.state().view().light().thetaDeg(), 1e-12);
            press(controller, (short) 0, 'p');
            assertTrue(model.state().notice().text().contains("no pigmentation image"));
            press(controller, (short) 0, 'r');
            assertEquals(Variant.FLSS, model.state().settings().variant());
            assertEquals(8, model.state().settings().taylor().highestOrder());
            assertEquals(10, model.state().terms().highestOrder(), "reset keeps the precomputed terms");
            assertEquals(30, model.state().view().light().thetaDeg(), 1e-12);
            controller.handleKey((short) 0, 'q');
            assertTrue(quit[0], "Q quits at once, without waiting for the render loop");
            assertEquals(0, controller.queuedInput());
            assertNull(model.state().precompute());
        }
    }

    /** Applies a key press as the render loop would: queued by the input listener, then applied. */
    private static void press(ViewerController controller, short keyCode, char keyChar) throws InterruptedException {
        controller.handleKey(keyCode, keyChar);
        controller.applyQueuedInput(0);
    }

    @Test
    void aMethodThatSamplesTheLightAtItsCentreDrawsTheScenesLightAsAPointAndSaysSo() throws InterruptedException {
        ViewerModel model = ViewerModel.load(ViewerTestSupport.setup().withSettings(ViewerTestSupport.settings()
                .with(b -> b.variant(Variant.LOBES).lightSizeDeg(2))), diffract.util.Reporter.SILENT);
        try (TermPrecomputer precomputer = new TermPrecomputer(model)) {
            ViewerController controller = new ViewerController(model, precomputer, () -> null, () -> { });
            assertEquals(2, model.state().drawableSettings().illumination().light().angularDiameterDeg());
            press(controller, (short) 0, '1');
            String expected = diffract.optics.LightPolicy.of(model.state().settings()).notice().orElseThrow();
            assertEquals(expected, model.state().notice().text());
            assertEquals(0, model.state().drawableSettings().illumination().light().angularDiameterDeg());
            assertEquals(2, model.state().settings().illumination().light().angularDiameterDeg(), "the scene's light "
                    + "is kept");
            press(controller, (short) 0, '4');
            assertEquals(2, model.state().drawableSettings().illumination().light().angularDiameterDeg());
        }
    }

    @Test
    void keysPressedWhileTheLoopIsBusyWaitInTheQueueAndAllApplyInOrder() throws InterruptedException {
        ViewerModel model = ViewerTestSupport.model(ViewerTestSupport.directTerms());
        try (TermPrecomputer precomputer = new TermPrecomputer(model)) {
            ViewerController controller = new ViewerController(model, precomputer, () -> null, () -> { });
            double exposure = model.state().view().exposure();
            double theta = model.state().view().light().thetaDeg();
            // a burst of input while the render loop draws a tile: nothing applies until the loop reads the queue
            for (int i = 0; i < 3; i++) {
                controller.handleKey(com.jogamp.newt.event.KeyEvent.VK_PAGE_UP, '\0');
            }
            controller.handleKey(com.jogamp.newt.event.KeyEvent.VK_DOWN, '\0');
            controller.handleKey((short) 0, ']');
            controller.handleKey((short) 0, '[');
            controller.handleKey((short) 0, '[');
            assertEquals(7, controller.queuedInput());
            assertEquals(exposure, model.state().view().exposure());
            assertEquals(7, controller.applyQueuedInput(0));
            assertEquals(exposure * Math.pow(ViewerController.EXPOSURE_STEP, 3), model.state().view().exposure(), 1e-9);
            assertEquals(theta + 5, model.state().view().light().thetaDeg(), 1e-12);
            // 20 -> 40 -> 20 -> 10: in the order pressed
            assertEquals(10, model.state().settings().spectral().lambdaStepNm());
            assertEquals(0, controller.queuedInput());
        }
    }

    @Test
    void titleNamesVariantParametersAndProgress() {
        ViewerModel model = ViewerTestSupport.model(ViewerTestSupport.directTerms());
        ViewerState state = model.update(s -> s.withSettings(s.settings().with(b -> b.highestOrder(12)))
                .withPrecompute(new PrecomputeProgress(12, 0.4)));
        String title = ViewerTitle.of(model, state, new FrameStats(), RefinementStatus.STARTING, System.nanoTime());
        assertEquals("diffract test-patch | flss N=8 dlambda=20 nm R=1 | theta_i 30 phi_i 90 | sphere | exposure 10"
                + " | starting | - ms/frame | precomputing N=12 40%", title);
        FrameStats stats = new FrameStats();
        stats.record(1234.4);
        ViewerState baking = model.update(s -> s.withPrecompute(null).withBake(new BakeProgress(0.407)));
        String refining = ViewerTitle.of(model, baking, stats, new RefinementStatus(RefinementStatus.Stage.REFINING, 4,
                0.375, baking, 3, 1), System.nanoTime());
        assertTrue(refining.endsWith(" | exposure 10 | refining 1/4 37% | 1234 ms/frame | baking table 40%"
                + " | N=12 waiting for terms"), refining);
        assertTrue(ViewerTitle.of(model, baking, stats, new RefinementStatus(RefinementStatus.Stage.PREVIEW, 8, 0,
                baking, 0, 0), System.nanoTime()).contains(" | preview 1/8 | "));
        assertTrue(ViewerTitle.of(model, baking, stats, new RefinementStatus(RefinementStatus.Stage.REFINING, 1, 0.5,
                baking, 0, 0), System.nanoTime()).contains(" | refining full size 50% | "));
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
