package diffract.viewer;

import com.jogamp.newt.event.KeyEvent;
import com.jogamp.newt.event.MouseEvent;
import diffract.jrtr.GlTestSupport;
import diffract.optics.Variant;
import diffract.scene.DisplayMode;
import diffract.scene.LightDirection;
import diffract.scene.OrbitCamera;
import diffract.util.TestReport;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The viewer's real window under Xvfb, driven by NEWT input events handed to the controller's listeners: drags,
 * keys, the background precompute, screenshots. One 128 x 128 window for the class (opening one costs a second).
 * Nothing here counts frames or times them: each test waits (with a generous ceiling) for the event it needs, most
 * often "the window shows the refined picture of the model's state".
 */
@Tag("gl")
@Tag(GlTestSupport.WINDOW_TAG)
class ViewerWindowTest {
    static final int SIZE_PX = 128;
    @TempDir
    static Path screenshots;
    static ViewerModel model;
    static ViewerWindow viewer;
    /** Terms beyond the initial N wait for this: the test decides when a background precompute may finish. */
    static final CountDownLatch PRECOMPUTE_MAY_FINISH = new CountDownLatch(1);

    @BeforeAll
    static void open() {
        if (diffract.jrtr.contexts.DisplayCheck.problem().isPresent()) {
            return;
        }
        model = ViewerTestSupport.model(ViewerTestSupport.gatedTerms(PRECOMPUTE_MAY_FINISH));
        viewer = new ViewerWindow(model, SIZE_PX, SIZE_PX, screenshots);
        viewer.start();
    }

    @AfterAll
    static void close() {
        if (viewer != null) {
            viewer.close();
        }
    }

    @BeforeEach
    void resetModel() throws InterruptedException {
        GlTestSupport.assumeWindow();
        model.reset(null);
        awaitRefined(); // so every test starts from the refined picture of the reset state
    }

    @Test
    void orbitDragChangesTheRenderedImage() throws InterruptedException {
        float[] before = viewer.shown().rgba();
        OrbitCamera cameraBefore = model.state().view().camera();
        var mouse = viewer.controller().mouseListener();
        mouse.mousePressed(mouse(MouseEvent.EVENT_MOUSE_PRESSED, 40, 64, MouseEvent.BUTTON1));
        mouse.mouseDragged(mouse(MouseEvent.EVENT_MOUSE_DRAGGED, 70, 64, MouseEvent.BUTTON1));
        mouse.mouseDragged(mouse(MouseEvent.EVENT_MOUSE_DRAGGED, 100, 50, MouseEvent.BUTTON1));
        double azimuth = cameraBefore.azimuthDeg() - 60 * ViewerController.ORBIT_DEG_PER_PX;
        double elevation = cameraBefore.elevationDeg() - 14 * ViewerController.ORBIT_DEG_PER_PX;
        // the drags are queued for the render loop, which applies both
        assertTrue(ViewerTestSupport.waitFor(() -> Math.abs(model.state().view().camera().azimuthDeg() - azimuth)
                < 1e-9 && Math.abs(model.state().view().camera().elevationDeg() - elevation) < 1e-9, 60));
        awaitRefined();
        float[] after = viewer.shown().rgba();
        int differing = differingPixels(before, after);
        TestReport.printf(ViewerWindowTest.class, "orbit drag of 60 x -14 px: %d of %d window pixels changed%n", differing, SIZE_PX * SIZE_PX);
        assertTrue(differing > 100, "only " + differing + " pixels changed");
    }

    @Test
    void rightDragMovesTheLightAndTheWheelZooms() throws InterruptedException {
        var mouse = viewer.controller().mouseListener();
        LightDirection light = model.state().view().light();
        double distance = model.state().view().camera().distance();
        mouse.mousePressed(mouse(MouseEvent.EVENT_MOUSE_PRESSED, 64, 64, MouseEvent.BUTTON3));
        mouse.mouseDragged(mouse(MouseEvent.EVENT_MOUSE_DRAGGED, 84, 74, MouseEvent.BUTTON3));
        mouse.mouseWheelMoved(new MouseEvent(MouseEvent.EVENT_MOUSE_WHEEL_MOVED, viewer.window().glWindow(),
                System.currentTimeMillis(), 0, 64, 64, (short) 0, (short) 0, new float[] {0, 2, 0}, 1f));
        assertTrue(ViewerTestSupport.waitFor(() -> Math.abs(model.state().view().camera().distance() - distance * 0.81)
                < 1e-9, 60), "the wheel was not applied");
        assertEquals(light.thetaDeg() + 10 * ViewerController.LIGHT_DEG_PER_PX, model.state().view().light().thetaDeg(), 1e-9);
        assertEquals(light.phiDeg() + 20 * ViewerController.LIGHT_DEG_PER_PX, model.state().view().light().phiDeg(), 1e-9);
    }

    @Test
    void variantKeySwitchesTheModelAndTheTitle() throws InterruptedException {
        press('3');
        assertTrue(ViewerTestSupport.waitFor(() -> model.state().settings().variant() == Variant.PQ, 60));
        assertTrue(ViewerTestSupport.waitFor(() -> viewer.title().contains("| pq N=8"), 60), viewer.title());
        assertTrue(ViewerTestSupport.waitFor(() -> viewer.window().glWindow().getTitle().contains("| pq N=8"), 60));
        press('2');
        assertTrue(ViewerTestSupport.waitFor(() -> model.state().settings().variant() == Variant.NMM, 60));
        assertTrue(ViewerTestSupport.waitFor(() -> viewer.title().contains("| nmm N=8"), 60), viewer.title());
        press('1');
        awaitRefined();
        assertTrue(ViewerTestSupport.waitFor(() -> viewer.title().matches(".*\\| flss N=8 .*\\| refined \\| \\d+ ms/frame.*"),
                60), viewer.title());
    }

    @Test
    void plusPrecomputesInTheBackgroundWhileTheWindowKeepsAnswering() throws InterruptedException {
        int before = model.state().terms().highestOrder();
        press('+');
        assertTrue(ViewerTestSupport.waitFor(() -> model.state().settings().taylor().highestOrder() == before + 1, 60));
        assertTrue(ViewerTestSupport.waitFor(() -> viewer.title().contains("precomputing N=" + (before + 1)), 60),
                "the title never showed the precompute: " + viewer.title());
        // the precompute waits for the gate: however slow the machine, the window must take input and refine meanwhile
        for (int i = 0; i < 2; i++) {
            double exposure = model.state().view().exposure();
            viewer.controller().keyListener().keyPressed(KeyEvent.create(KeyEvent.EVENT_KEY_PRESSED,
                    viewer.window().glWindow(), System.currentTimeMillis(), 0, KeyEvent.VK_PAGE_UP, KeyEvent.VK_PAGE_UP,
                    '\0'));
            assertTrue(ViewerTestSupport.waitFor(() -> model.state().view().exposure() > exposure, 60));
            awaitRefined();
        }
        assertEquals(before, model.state().terms().highestOrder(), "the terms arrived before the gate opened");
        assertTrue(viewer.title().contains("precomputing N="), viewer.title());
        PRECOMPUTE_MAY_FINISH.countDown();
        assertTrue(ViewerTestSupport.waitFor(() -> model.state().terms().highestOrder() == before + 1, 300),
                "terms never arrived");
        assertTrue(ViewerTestSupport.waitFor(() -> viewer.title().contains("flss N=" + (before + 1)), 60),
                viewer.title());
        awaitRefined();
        assertEquals(null, model.state().precompute());
    }

    @Test
    void materialsAreNotRebuiltPerFrame() throws InterruptedException {
        int builds = viewer.renderer().materialBuildCount();
        // exposure changes redraw every pass of the refinement, preview and configured, with the materials at hand
        for (short key : new short[] {KeyEvent.VK_PAGE_UP, KeyEvent.VK_PAGE_DOWN, KeyEvent.VK_PAGE_UP}) {
            double exposure = model.state().view().exposure();
            viewer.controller().keyListener().keyPressed(KeyEvent.create(KeyEvent.EVENT_KEY_PRESSED,
                    viewer.window().glWindow(), System.currentTimeMillis(), 0, key, key, '\0'));
            assertTrue(ViewerTestSupport.waitFor(() -> model.state().view().exposure() != exposure, 60));
            awaitRefined();
        }
        assertEquals(builds, viewer.renderer().materialBuildCount());
    }

    @Test
    void screenshotKeySavesAPngOfTheWindow() throws Exception {
        press('s');
        assertTrue(ViewerTestSupport.waitFor(() -> pngs().size() > 0, 60), "no screenshot written");
        Path png = pngs().get(0);
        BufferedImage image = ImageIO.read(png.toFile());
        assertEquals(viewer.window().surfaceWidth(), image.getWidth());
        assertEquals(viewer.window().surfaceHeight(), image.getHeight());
        int centre = image.getRGB(image.getWidth() / 2, image.getHeight() / 2) & 0xffffff;
        int clear = Math.round(ViewerRenderer.CLEAR_COLOUR[0] * 255) << 16
                | Math.round(ViewerRenderer.CLEAR_COLOUR[1] * 255) << 8 | Math.round(ViewerRenderer.CLEAR_COLOUR[2] * 255);
        assertNotEquals(clear, centre, "the sphere is not in the middle of the screenshot");
    }

    @Test
    void brdfMapKeyShowsTheMapAndHelpGoesToTheTitle() throws InterruptedException {
        press('b');
        assertTrue(ViewerTestSupport.waitFor(() -> model.state().view().mode() == DisplayMode.BRDF_MAP, 60));
        assertTrue(ViewerTestSupport.waitFor(() -> viewer.title().contains("BRDF map"), 60), viewer.title());
        awaitRefined();
        float[] map = viewer.shown().rgba();
        // outside the unit disk the map is black, unlike the surface mode's grey background
        assertEquals(0f, map[0] + map[1] + map[2], 1e-6f);
        press('h');
        assertTrue(ViewerTestSupport.waitFor(() -> viewer.title().contains("right-drag light"), 60), viewer.title());
        press('b');
        assertTrue(ViewerTestSupport.waitFor(() -> model.state().view().mode() == DisplayMode.SURFACE, 60));
    }

    static void awaitRefined() throws InterruptedException {
        assertTrue(ViewerTestSupport.awaitRefined(viewer, model), "never refined: " + viewer.refinement());
    }

    static void press(char key) {
        short code = KeyEvent.utf16ToVKey(key);
        viewer.controller().keyListener().keyPressed(KeyEvent.create(KeyEvent.EVENT_KEY_PRESSED,
                viewer.window().glWindow(), System.currentTimeMillis(), 0, code, code, key));
    }

    static MouseEvent mouse(short type, int x, int y, short button) {
        return new MouseEvent(type, viewer.window().glWindow(), System.currentTimeMillis(), 0, x, y, (short) 1, button,
                new float[] {0, 0, 0}, 1f);
    }

    static int differingPixels(float[] a, float[] b) {
        int count = 0;
        for (int p = 0; p < a.length; p += 4) {
            if (Math.abs(a[p] - b[p]) + Math.abs(a[p + 1] - b[p + 1]) + Math.abs(a[p + 2] - b[p + 2]) > 0.02f) {
                count++;
            }
        }
        return count;
    }

    static List<Path> pngs() {
        try (Stream<Path> files = Files.list(screenshots)) {
            return files.filter(f -> f.toString().endsWith(".png")).collect(Collectors.toList());
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
