package diffract.viewer;

import com.jogamp.newt.event.KeyEvent;
import com.jogamp.newt.event.MouseEvent;
import diffract.jrtr.GlTestSupport;
import diffract.optics.Variant;
import diffract.render.BakedTables;
import diffract.util.Reporter;
import diffract.util.ImageFiles;
import diffract.util.TestCache;
import diffract.util.TestReport;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The viewer never looks hung: a window whose configured frame is deliberately expensive (minutes on llvmpipe,
 * {@link ViewerTestSupport#expensiveModel}) shows a picture of the scene before that frame is done, takes every key
 * pressed while it draws, names the refinement stage in its title, and quits on Q while the expensive frame is under
 * way. So that this holds on a machine of any speed (a GPU may draw that frame at once), the window holds the
 * refinement's last pass after its first tile ({@link ViewerWindow#holdLastPass}): the expensive frame stays under
 * way for as long as a test needs. The assertions are about the order of events, read from the refinement's own
 * counters; the one bound on time, the quit's, is loose, so a busy machine does not fail it.
 */
@Tag("gl")
@Tag(GlTestSupport.WINDOW_TAG)
class ViewerResponsivenessTest {
    static final int SIZE_PX = 128;
    /** The loose ceiling of a quit; the design answers within about one tile ({@link RefiningRenderer#TILE_MS}). */
    static final double QUIT_CEILING_S = 10;
    @TempDir
    Path screenshots;
    ViewerModel model;
    ViewerWindow viewer;

    void open(ViewerModel m) {
        open(m, false);
    }

    /** A window on {@code m}; {@code holdLastPass}: its last pass stays under way after its first tile. */
    void open(ViewerModel m, boolean holdLastPass) {
        GlTestSupport.assumeWindow();
        model = m;
        viewer = new ViewerWindow(model, SIZE_PX, SIZE_PX, screenshots);
        viewer.holdLastPass(holdLastPass);
        viewer.start();
    }

    /** The expensive model, its last pass held under way. */
    void openExpensive() {
        open(ViewerTestSupport.expensiveModel(), true);
    }

    @AfterEach
    void close() {
        if (viewer != null) {
            viewer.close();
        }
    }

    @Test
    void aPictureOfTheSceneComesBeforeTheExpensiveFrame() throws InterruptedException, IOException {
        openExpensive();
        assertTrue(ViewerTestSupport.waitFor(() -> viewer.refinement().passesCompleted() >= 1, 300),
                "no pass completed: " + viewer.refinement());
        RefiningRenderer.Shown shown = viewer.shown();
        // what the window showed, and where the refinement stood at that moment
        assertEquals(0, shown.status().refinedFrames(), "the expensive frame came first");
        assertNotEquals(RefinementStatus.Stage.REFINED, shown.status().stage());
        int background = 0;
        int coloured = 0;
        float[] clear = ViewerRenderer.CLEAR_COLOUR;
        float[] rgba = shown.rgba();
        for (int p = 0; p < rgba.length; p += 4) {
            float r = rgba[p];
            float g = rgba[p + 1];
            float b = rgba[p + 2];
            if (Math.abs(r - clear[0]) + Math.abs(g - clear[1]) + Math.abs(b - clear[2]) < 0.02f) {
                background++;
            } else if (Math.max(r, Math.max(g, b)) - Math.min(r, Math.min(g, b)) > 0.1f) {
                coloured++;
            }
        }
        int pixels = SIZE_PX * SIZE_PX;
        float[] rgb = new float[pixels * 3];
        for (int p = 0; p < pixels; p++) {
            System.arraycopy(rgba, 4 * p, rgb, 3 * p, 3);
        }
        ImageFiles.writePng(TestReport.DIR.resolve("ViewerResponsivenessTest-first-picture.png"), rgb, SIZE_PX, SIZE_PX, 3);
        TestReport.printf(ViewerResponsivenessTest.class, "first picture (%s 1/%d, %d passes done): %d of %d pixels"
                        + " background, %d coloured%n", shown.status().stage(), shown.status().divisor(),
                shown.status().passesCompleted(), background, pixels, coloured);
        // the sphere (radius 1 at distance 3 under a 45 degree field of view: 2/3 of the height across) on the grey
        // background, the orders in colour on it
        assertTrue(background > pixels / 5 && background < pixels * 0.9, background + " background pixels");
        assertTrue(coloured > pixels / 200, coloured + " coloured pixels");
    }

    @Test
    void qQuitsWhileTheExpensiveFrameIsDrawn() throws InterruptedException {
        openExpensive();
        awaitExpensivePass();
        RefinementStatus atQ = viewer.refinement();
        long start = System.nanoTime();
        press('q');
        assertTrue(viewer.isCloseRequested(), "Q asks to quit at once, on the input thread");
        viewer.close();
        double seconds = (System.nanoTime() - start) / 1e9;
        RefinementStatus end = viewer.refinement();
        ViewerWindow closed = viewer;
        viewer = null;
        TestReport.printf(ViewerResponsivenessTest.class, "Q during the expensive pass (1/%d, %.0f%% drawn): window"
                + " closed after %.2f s; passes completed %d at Q, %d at the end%n", atQ.divisor(),
                100 * atQ.fraction(), seconds, atQ.passesCompleted(), end.passesCompleted());
        assertFalse(closed.isDrawing(), "the render loop still draws");
        // the quit did not wait for the expensive frame: its full-resolution pass was never reached
        assertEquals(0, end.refinedFrames());
        assertTrue(end.passesCompleted() < RefiningRenderer.LADDER.size(), end.toString());
        assertTrue(seconds < QUIT_CEILING_S, "the quit took " + seconds + " s");
    }

    @Test
    void keysPressedDuringTheExpensivePassAreAllApplied() throws InterruptedException {
        openExpensive();
        awaitExpensivePass();
        ViewerState before = model.state();
        // a burst of input while the render loop draws a tile of the expensive frame
        for (int i = 0; i < 3; i++) {
            pressCode(KeyEvent.VK_PAGE_UP);
        }
        pressCode(KeyEvent.VK_UP);
        pressCode(KeyEvent.VK_UP);
        press(']');
        viewer.controller().mouseListener().mouseWheelMoved(new MouseEvent(MouseEvent.EVENT_MOUSE_WHEEL_MOVED,
                viewer.window().glWindow(), System.currentTimeMillis(), 0, 64, 64, (short) 0, (short) 0,
                new float[] {0, 1, 0}, 1f));
        double exposure = before.view().exposure() * Math.pow(ViewerController.EXPOSURE_STEP, 3);
        assertTrue(ViewerTestSupport.waitFor(() -> Math.abs(model.state().view().camera().distance()
                - before.view().camera().distance() * ViewerController.ZOOM_PER_WHEEL_STEP) < 1e-9, 120),
                "the last input never arrived");
        ViewerState after = model.state();
        assertEquals(exposure, after.view().exposure(), 1e-9);
        assertEquals(before.view().light().thetaDeg() - 10, after.view().light().thetaDeg(), 1e-9);
        assertEquals(2, after.settings().spectral().lambdaStepNm());
        // the window refines the new state, and its title says so
        assertTrue(ViewerTestSupport.waitFor(() -> viewer.refinement().state() != null
                && viewer.refinement().state().view().equals(after.view()), 120), viewer.refinement().toString());
        assertTrue(ViewerTestSupport.waitFor(() -> viewer.title().contains("dlambda=2 nm")
                && viewer.title().contains("exposure " + ViewerTitle.number(exposure)), 120), viewer.title());
    }

    @Test
    void theTitleNamesTheRefinementStage() throws InterruptedException {
        openExpensive();
        assertTrue(ViewerTestSupport.waitFor(() -> viewer.title().matches(".*\\| refining 1/\\d+ \\d+% \\|.*"), 300),
                viewer.title());
    }

    @Test
    void theBakedVariantShowsThePreviewWhileItsTableBakesThenRefinesWithIt(@TempDir Path cacheDir)
            throws InterruptedException {
        GlTestSupport.assumeWindow();
        try (TestCache ignored = TestCache.at(cacheDir)) { // empty: the table must be baked
            // N = 20: the thesis' series reaches this patch, which the baked table is made of
            ViewerModel m = ViewerModel.load(ViewerTestSupport.setup().withSettings(ViewerTestSupport.settings()
                    .with(b -> b.variant(Variant.BAKED).highestOrder(20).bakedSamples(24, 8))), Reporter.SILENT);
            BakedTables tables = m.pipeline().tables();
            tables.forgetInMemory(); // as a new process
            int bakes = tables.bakeCount();
            open(m);
            assertTrue(ViewerTestSupport.awaitRefined(viewer, model), viewer.refinement().toString());
            assertEquals(bakes + 1, tables.bakeCount(), "the window baked the table once");
            assertTrue(tables.isBaked(model.state().terms(), model.state().drawableSettings()));
            assertNull(model.state().bake());
            assertEquals(Variant.BAKED, viewer.refinement().state().drawableSettings().variant());
            assertTrue(ViewerTestSupport.waitFor(() -> viewer.title().contains("| baked N=20")
                    && viewer.title().contains("| refined |"), 60), viewer.title());
        }
    }

    /** A table in the disk cache is loaded, not baked: the window never waits for a bake. */
    @Test
    void theBakedVariantDrawsATableFromTheDiskCacheWithoutABake(@TempDir Path cacheDir) throws InterruptedException {
        GlTestSupport.assumeWindow();
        try (TestCache ignored = TestCache.at(cacheDir)) {
            ViewerModel m = ViewerModel.load(ViewerTestSupport.setup().withSettings(ViewerTestSupport.settings()
                    .with(b -> b.variant(Variant.BAKED).highestOrder(20).bakedSamples(24, 8))), Reporter.SILENT);
            new BakedTables().of(m.state().terms(), m.state().drawableSettings(), Reporter.SILENT); // an earlier run
            BakedTables tables = m.pipeline().tables();
            tables.forgetInMemory(); // as a new process
            int bakes = tables.bakeCount();
            int loads = tables.loadCount();
            open(m);
            assertTrue(ViewerTestSupport.awaitRefined(viewer, model), viewer.refinement().toString());
            assertEquals(bakes, tables.bakeCount(), "the window baked nothing");
            assertEquals(loads + 1, tables.loadCount(), "it loaded the table once");
            assertNull(model.state().bake(), "no bake was started");
            assertEquals(Variant.BAKED, viewer.refinement().state().drawableSettings().variant());
        }
    }

    /**
     * The hold the other tests rely on: a cheap picture, which the window refines in a few seconds unheld, stays in
     * its last pass, and refines once the hold is let go.
     */
    @Test
    void aHeldLastPassStaysUnderWayUntilLetGo() throws InterruptedException {
        ViewerModel cheap = ViewerModel.load(ViewerTestSupport.setup(), Reporter.SILENT);
        open(cheap, true);
        awaitLastPass();
        Thread.sleep(2000);
        RefinementStatus held = viewer.refinement();
        assertEquals(RefinementStatus.Stage.REFINING, held.stage(), held.toString());
        assertEquals(1, held.divisor(), held.toString());
        assertEquals(0, held.refinedFrames(), held.toString());
        viewer.holdLastPass(false); // the loop looks again within its idle wait
        assertTrue(ViewerTestSupport.awaitRefined(viewer, model), viewer.refinement().toString());
    }

    /** Waits until the last pass (the full resolution) has drawn at least one tile. */
    void awaitLastPass() throws InterruptedException {
        assertTrue(ViewerTestSupport.waitFor(() -> viewer.refinement().stage() == RefinementStatus.Stage.REFINING
                && viewer.refinement().divisor() == 1 && viewer.refinement().fraction() > 0, 300),
                "the last pass never started: " + viewer.refinement());
    }

    /** Waits until the expensive configured pass has drawn at least one tile. */
    void awaitExpensivePass() throws InterruptedException {
        assertTrue(ViewerTestSupport.waitFor(() -> viewer.refinement().stage() == RefinementStatus.Stage.REFINING
                && viewer.refinement().fraction() > 0, 300), "the expensive pass never started: " + viewer.refinement());
    }

    void press(char key) {
        short code = KeyEvent.utf16ToVKey(key);
        viewer.controller().keyListener().keyPressed(KeyEvent.create(KeyEvent.EVENT_KEY_PRESSED,
                viewer.window().glWindow(), System.currentTimeMillis(), 0, code, code, key));
    }

    void pressCode(short code) {
        viewer.controller().keyListener().keyPressed(KeyEvent.create(KeyEvent.EVENT_KEY_PRESSED,
                viewer.window().glWindow(), System.currentTimeMillis(), 0, code, code, '\0'));
    }
}
