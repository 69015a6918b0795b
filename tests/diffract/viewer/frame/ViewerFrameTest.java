package diffract.viewer.frame;

import com.jogamp.newt.event.KeyEvent;
import diffract.colour.DeltaEStatistics;
import diffract.colour.Srgb;
import diffract.jrtr.GlTestSupport;
import diffract.jrtr.OffscreenTarget;
import diffract.optics.settings.LightProfile;
import diffract.optics.Variant;
import diffract.scene.DisplayMode;
import diffract.scene.Fabricator;
import diffract.scene.Scene;
import diffract.scene.SceneFile;
import diffract.scene.SceneSetup;
import diffract.util.Reporter;
import diffract.util.TestReport;
import diffract.viewer.ViewerModel;
import diffract.viewer.ViewerRenderer;
import diffract.viewer.ViewerState;
import diffract.viewer.ViewerWindow;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.io.TempDir;

import javax.imageio.ImageIO;
import javax.swing.AbstractButton;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JDialog;
import javax.swing.JList;
import javax.swing.JSlider;
import javax.swing.TransferHandler;
import java.awt.Component;
import java.awt.Container;
import java.awt.Window;
import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.Transferable;
import java.awt.event.MouseEvent;
import java.awt.image.BufferedImage;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.function.BooleanSupplier;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The viewer's frame driven as a user drives it, under Xvfb: every control of the settings panel changes the view's
 * state (a refused one is disabled with its reason), the keys still work and move the controls, the light is dragged
 * on its hemisphere, the BRDF-map inset draws the light's map, the A/B split draws the right half with the other
 * method and the left half as before, a scene and a .gwy scan are opened by drag and drop (the scan's channel picked in
 * its dialog), the picture and the scene are saved and {@code render} of the saved scene draws the view's picture, and
 * the view's method is compared with the exact reference on the BRDF map. Nothing is timed: each step waits for the
 * state or the picture it needs, with a generous ceiling.
 */
@Tag("gl")
@Tag(GlTestSupport.WINDOW_TAG)
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class ViewerFrameTest {
    static final int W = 160;
    static final int H = 120;
    @TempDir
    static Path dir;
    static ViewerFrame frame;
    static Scene scene;

    /** A small sphere scene: a 32-pixel Elaphe-like patch, FLSS with 8 terms at 20 nm, 10 um coherence. */
    static final String SCENE = """
            {
              "image": {"width": 160, "height": 120},
              "camera": {"eye": [0, 1.03, 2.82], "lookAt": [0, 0, 0], "up": [0, 1, 0], "fieldOfViewDeg": 45},
              "light": {"thetaDeg": 30, "phiDeg": 90},
              "shape": {"kind": "sphere"},
              "material": {
                "patch": {"procedural": "elaphe-like", "sizePx": 32, "periods": 2},
                "variant": "flss", "taylorTerms": 8, "lambdaStepNm": 20, "windowRadius": 1,
                "coherenceLengthUm": 10, "diffuseWeight": 0.2, "exposure": 10
              },
              "mode": "surface"
            }
            """;

    @BeforeAll
    static void open() throws Exception {
        if (diffract.jrtr.contexts.DisplayCheck.problem().isPresent()) {
            return;
        }
        Path file = dir.resolve("sphere.json");
        Files.writeString(file, SCENE);
        scene = SceneFile.load(file);
        SceneSetup setup = Fabricator.fabricate(scene, Reporter.SILENT);
        frame = new ViewerFrame(scene, ViewerModel.load(setup, Reporter.SILENT), W, H, dir.resolve("shots"),
                (current, kind) -> current, new RecentFiles(dir.resolve("recent")), Reporter.SILENT);
    }

    @AfterAll
    static void close() {
        if (frame != null) {
            frame.close();
        }
    }

    @BeforeEach
    void ready() throws InterruptedException {
        GlTestSupport.assumeWindow();
        assertTrue(waitFor(() -> frame.view() != null, 60));
    }

    static ViewerState state() {
        return frame.view().model().state();
    }

    @Test
    @Order(1)
    void everyControlChangesTheViewAndRefusedOnesSayWhy() throws Exception {
        SettingsPanel p = frame.settings();
        assertEquals(List.of("method", "N", "wavelength step", "coherence length", "light size", "light profile",
                "window R", "exposure", "pigment", "shape", "mode", "A/B", "B method", "divider"), p.names());
        select(p, "method", "nmm");
        awaitState(() -> state().settings().variant() == Variant.NMM, "method");
        slide(p, "N", 10);
        awaitState(() -> state().settings().taylor().highestOrder() == 10, "N");
        select(p, "method", "flss");
        awaitState(() -> state().settings().variant() == Variant.FLSS, "method back");
        select(p, "wavelength step", "10 nm");
        awaitState(() -> state().settings().spectral().lambdaStepNm() == 10, "wavelength step");
        select(p, "coherence length", "20 um");
        awaitState(() -> Math.abs(4 * state().settings().illumination().sigmaSpatialUm() - 20) < 1e-9, "coherence");
        select(p, "window R", "2");
        awaitState(() -> state().settings().window().radius() == 2 && !state().settings().window().automatic(),
                "window");
        slide(p, "exposure", SettingsPanel.sliderOf(40));
        awaitState(() -> Math.abs(state().view().exposure() - Math.pow(2, SettingsPanel.sliderOf(40) / 2.0)) < 1e-9,
                "exposure");
        // FLSS samples the light at its centre: the light's size is refused, with the reason
        awaitPanel(() -> !p.control("light size").isEnabled(), "light size disabled for flss");
        assertTrue(p.reason("light size").contains("samples the light at its centre"), p.reason("light size"));
        assertTrue(p.reason("pigment").contains("no pigmentation image"), p.reason("pigment"));
        select(p, "method", "lobes");
        awaitState(() -> state().settings().variant() == Variant.LOBES, "lobes");
        awaitPanel(() -> p.control("light size").isEnabled() && !p.control("wavelength step").isEnabled(),
                "the lobes method takes the light's size and steps through no wavelengths");
        assertTrue(p.reason("wavelength step").contains("lobes"), p.reason("wavelength step"));
        select(p, "light size", "2 deg");
        awaitState(() -> state().settings().illumination().light().angularDiameterDeg() == 2, "light size");
        select(p, "light profile", LightProfile.GAUSSIAN.label());
        awaitState(() -> state().settings().illumination().light().profile() == LightProfile.GAUSSIAN, "profile");
        click(p, "mode");
        awaitState(() -> state().view().mode() == DisplayMode.BRDF_MAP, "BRDF map");
        click(p, "mode");
        awaitState(() -> state().view().mode() == DisplayMode.SURFACE, "surface");
        click(p, "A/B");
        awaitState(() -> state().view().split() != null, "split on");
        select(p, "B method", "pq");
        awaitState(() -> state().view().split() != null && state().view().split().other().variant() == Variant.PQ,
                "B method");
        slide(p, "divider", 30);
        awaitState(() -> state().view().split() != null && Math.abs(state().view().split().divider() - 0.3) < 1e-9,
                "divider");
        click(p, "A/B");
        awaitState(() -> state().view().split() == null, "split off");
        // the keys still work, and the controls follow them
        press('1');
        awaitState(() -> state().settings().variant() == Variant.FLSS, "key 1");
        awaitPanel(() -> "flss".equals(((JComboBox<?>) p.control("method")).getSelectedItem()), "the combo follows");
        assertTrue(waitFor(() -> frame.status().text().contains("refined"), 300), frame.status().text());
        frame.view().model().reset(null);
    }

    @Test
    @Order(2)
    void theLightIsDraggedOnItsHemisphereAndTheInsetDrawsItsMap() throws Exception {
        LightWidget widget = frame.lightWidget();
        int[] target = new int[2];
        ViewerFrame.onEdt(() -> {
            int[] p = widget.pixelOf(45, 200);
            target[0] = p[0];
            target[1] = p[1];
            widget.dispatchEvent(new MouseEvent(widget, MouseEvent.MOUSE_PRESSED, System.currentTimeMillis(), 0,
                    p[0], p[1], 1, false, MouseEvent.BUTTON1));
        });
        double[] expected = widget.directionAt(target[0], target[1]);
        diffract.scene.LightDirection under = new diffract.scene.LightDirection(expected[0], expected[1]);
        awaitState(() -> state().view().light().equals(under), "the light under the pointer");
        assertEquals(45, expected[0], 1.5);
        assertEquals(200, expected[1], 1.5);
        assertTrue(waitFor(() -> frame.inset().showsCurrent() && frame.inset().image() != null, 300),
                "the inset never drew the map of the light");
        BufferedImage map = frame.inset().image();
        assertEquals(0, map.getRGB(2, 2) & 0xffffff, "black beyond the unit disc");
        assertFalse(frame.inset().orderLabels(state().view().light()).isEmpty(), "the orders are labelled");
        frame.view().model().reset(null);
    }

    @Test
    @Order(3)
    void theSplitDrawsTheOtherMethodRightOfTheDivider() throws Exception {
        frame.view().model().reset(null);
        awaitRefined();
        float[] whole = frame.view().shown().rgba();
        ViewerState s = state();
        frame.view().controller().queue(c -> c.setSplit(new ViewerState.Split(s.settings().with(b -> b.variant(
                Variant.PQ).pqReplicas(3)), 0.5)));
        awaitState(() -> state().view().split() != null, "split");
        awaitRefined();
        ViewerWindow v = frame.view();
        var shown = v.shown();
        int width = shown.width();
        int left = 0;
        int right = 0;
        for (int y = 0; y < shown.height(); y++) {
            for (int x = 0; x < width; x++) {
                int p = 4 * (y * width + x);
                boolean differs = Math.abs(shown.rgba()[p] - whole[p]) + Math.abs(shown.rgba()[p + 1] - whole[p + 1])
                        + Math.abs(shown.rgba()[p + 2] - whole[p + 2]) > 3 / 255f;
                if (differs && x < width / 2 - 1) {
                    left++;
                } else if (differs && x > width / 2 + 1) {
                    right++;
                }
            }
        }
        TestReport.printf(ViewerFrameTest.class, "split flss | pq: %d pixels differ left of the divider, %d right%n",
                left, right);
        assertEquals(0, left, "A's half is A's picture");
        assertTrue(right > 20, "B's half draws B: " + right);
        // the divider dragged in the view, as the mouse does it
        var mouse = frame.view().controller().mouseListener();
        var glWindow = frame.view().window().glWindow();
        int w = glWindow.getSurfaceWidth();
        mouse.mousePressed(newtMouse(com.jogamp.newt.event.MouseEvent.EVENT_MOUSE_PRESSED, w / 2, 20));
        mouse.mouseDragged(newtMouse(com.jogamp.newt.event.MouseEvent.EVENT_MOUSE_DRAGGED, w / 4, 20));
        awaitState(() -> state().view().split() != null && Math.abs(state().view().split().divider() - (w / 4)
                / (double) w) < 1e-9, "the divider dragged to a quarter");
        frame.view().controller().queue(c -> c.setSplit(null));
        frame.view().model().reset(null);
    }

    @Test
    @Order(5)
    void aDroppedSceneAndAGwyScanOpenAndThePictureAndSceneAreSaved() throws Exception {
        // a scene dropped on the frame: the grating plane
        Path plane = Path.of("assets", "scenes", "blazed-grating-plane.json").toAbsolutePath();
        ViewerWindow before = frame.view();
        assertTrue(drop(frame.dropTarget(), plane));
        assertTrue(waitFor(() -> frame.view() != before && frame.scene().source() != null
                && frame.scene().source().endsWith("blazed-grating-plane.json"), 300), "the scene never opened");
        assertEquals(Scene.ShapeKind.PLANE, frame.scene().shape().kind());
        assertTrue(new RecentFiles(dir.resolve("recent")).list().contains(plane));

        // a .gwy scan dropped: its channels listed, the height channel picked in the dialog
        Path gwy = Path.of("tests", "fixtures", "gwyfile-channels.gwy").toAbsolutePath();
        ViewerWindow beforeScan = frame.view();
        Thread dropper = new Thread(() -> drop(frame.dropTarget(), gwy));
        dropper.start();
        JDialog dialog = (JDialog) awaitWindow(ScanDialog.NAME);
        JList<?> channels = find(dialog, JList.class, "channels");
        String[] listed = new String[channels.getModel().getSize()];
        ViewerFrame.onEdt(() -> {
            for (int i = 0; i < listed.length; i++) {
                listed[i] = (String) channels.getModel().getElementAt(i);
            }
        });
        TestReport.printf(ViewerFrameTest.class, "channels of %s: %s%n", gwy.getFileName(), String.join("; ", listed));
        assertTrue(listed.length >= 2, String.join("; ", listed));
        int chosen = channels.getSelectedIndex();
        assertTrue(chosen >= 0 && listed[chosen].contains(" in m"), "the height channel is preselected: "
                + String.join("; ", listed));
        JButton open = findButton(dialog, "Open");
        ViewerFrame.onEdt(open::doClick);
        dropper.join(60_000);
        assertTrue(waitFor(() -> frame.view() != beforeScan && frame.scene().material().patch()
                instanceof Scene.FilePatch f && f.file().endsWith("gwyfile-channels.gwy"), 300), "the scan never opened");
        Scene.FilePatch patch = (Scene.FilePatch) frame.scene().material().patch();
        assertEquals(listed[chosen].substring(0, listed[chosen].indexOf(' ')), patch.channel());
        awaitRefined();

        // the picture and the scene saved; render of the saved scene draws what the view shows
        Path png = frame.savePicture(dir.resolve("view.png"));
        BufferedImage saved = ImageIO.read(png.toFile());
        var shown = frame.view().shown();
        assertEquals(shown.width(), saved.getWidth());
        Path exr = frame.savePicture(dir.resolve("view.exr"));
        assertTrue(Files.size(exr) > 1000);
        Path json = frame.saveScene(dir.resolve("view.json"));
        Scene reread = SceneFile.load(json);
        assertEquals(shown.width(), reread.image().width());
        SceneSetup again = Fabricator.fabricate(reread, Reporter.SILENT);
        float[] rendered;
        try (OffscreenTarget target = new OffscreenTarget(new ViewerRenderer(ViewerModel.load(again,
                Reporter.SILENT)))) {
            rendered = target.renderRgb(shown.width(), shown.height());
        }
        float[] window = new float[rendered.length];
        for (int p = 0; p < rendered.length / 3; p++) {
            System.arraycopy(shown.rgba(), 4 * p, window, 3 * p, 3);
        }
        DeltaEStatistics e = DeltaEStatistics.of(Srgb.xyzOfDisplayRgb(window), Srgb.xyzOfDisplayRgb(rendered), null);
        TestReport.printf(ViewerFrameTest.class, Locale.ROOT, "render of the saved scene against the view: CIEDE2000 "
                + "mean %.3f, max %.3f%n", e.mean(), e.max());
        assertTrue(e.mean() < 0.2, "render draws the saved scene as the view shows it: " + e.mean());
        assertThrows(() -> frame.savePicture(dir.resolve("view.gif")));
    }

    @Test
    @Order(4)
    void theMethodIsComparedWithTheReferenceOnTheMap() throws Exception {
        frame.view().model().reset(null);
        frame.view().controller().queue(c -> c.setMode(DisplayMode.BRDF_MAP));
        awaitState(() -> state().view().mode() == DisplayMode.BRDF_MAP, "map mode");
        Thread.sleep(2L * ViewerFrame.REFRESH_MS);
        ViewerFrame.onEdt(() -> frame.reference().start());
        assertTrue(waitFor(() -> frame.reference().last() != null && !frame.reference().isBusy(), 600),
                "no comparison");
        ReferencePanel.Comparison c = frame.reference().last();
        TestReport.printf(ViewerFrameTest.class, Locale.ROOT, "%s against the reference, %d px map: CIEDE2000 mean "
                + "%.2f, p95 %.2f over %d lit px, the reference in %.1f s%n", c.method().variant().spec(),
                ReferencePanel.SIZE_PX, c.statistics().mean(), c.statistics().p95(), c.statistics().pixels(),
                c.seconds());
        assertTrue(c.statistics().pixels() > 10, "lit pixels compared: " + c.statistics().pixels());
        assertTrue(c.statistics().mean() > 0 && c.statistics().mean() < 30, "mean " + c.statistics().mean());
        // a second look at the same light comes from the disk cache
        ViewerFrame.onEdt(() -> frame.reference().start());
        assertTrue(waitFor(() -> frame.reference().last() != c && !frame.reference().isBusy(), 600));
        assertEquals(c.statistics().mean(), frame.reference().last().statistics().mean(), 1e-9);
        // Maxwell's equations as the yardstick: refused on this 2-D patch, with the reason
        ViewerFrame.onEdt(() -> frame.reference().against(ReferencePanel.Yardstick.RIGOROUS));
        assertTrue(waitFor(() -> !frame.reference().canCompare(), 30), "the rigorous yardstick on a 2-D patch");
        assertTrue(frame.reference().reason().contains("1-D patches"), frame.reference().reason());
        ViewerFrame.onEdt(() -> frame.reference().against(ReferencePanel.Yardstick.REFERENCE));
        assertTrue(waitFor(() -> frame.reference().canCompare(), 30));
        frame.view().model().reset(null);
    }

    /** On a 1-D grating the method is measured against Maxwell's equations (the rigorous method's map). */
    @Test
    @Order(6)
    void onAGratingTheMethodIsComparedWithMaxwellsEquations() throws Exception {
        Path file = dir.resolve("grating.json");
        Files.writeString(file, SCENE.replace("{\"procedural\": \"elaphe-like\", \"sizePx\": 32, \"periods\": 2}",
                "{\"procedural\": \"blazed\", \"periods\": 4}").replace("\"surface\"", "\"brdfMap\""));
        ViewerWindow before = frame.view();
        frame.openScene(file).get(5, java.util.concurrent.TimeUnit.MINUTES);
        assertTrue(waitFor(() -> frame.view() != before && state().view().mode() == DisplayMode.BRDF_MAP, 300));
        Thread.sleep(2L * ViewerFrame.REFRESH_MS);
        ViewerFrame.onEdt(() -> frame.reference().against(ReferencePanel.Yardstick.RIGOROUS));
        assertTrue(waitFor(() -> frame.reference().canCompare(), 30), frame.reference().reason());
        ReferencePanel.Comparison earlier = frame.reference().last();
        ViewerFrame.onEdt(() -> frame.reference().start());
        assertTrue(waitFor(() -> frame.reference().last() != earlier && !frame.reference().isBusy(), 600),
                "no comparison");
        ReferencePanel.Comparison c = frame.reference().last();
        TestReport.printf(ViewerFrameTest.class, Locale.ROOT, "%s on the blazed grating against Maxwell's equations, "
                + "%d px map: CIEDE2000 mean %.2f, p95 %.2f over %d lit px, the rigorous map in %.1f s%n",
                c.method().variant().spec(), ReferencePanel.SIZE_PX, c.statistics().mean(), c.statistics().p95(),
                c.statistics().pixels(), c.seconds());
        assertEquals(ReferencePanel.Yardstick.RIGOROUS, c.yardstick());
        assertTrue(c.statistics().pixels() > 10, "lit pixels compared: " + c.statistics().pixels());
        assertTrue(c.statistics().mean() > 0 && c.statistics().mean() < 30, "mean " + c.statistics().mean());
    }

    // ---- driving Swing as a user does

    static void select(SettingsPanel p, String control, String item) {
        ViewerFrame.onEdt(() -> ((JComboBox<?>) p.control(control)).setSelectedItem(item));
    }

    static void slide(SettingsPanel p, String control, int value) {
        ViewerFrame.onEdt(() -> ((JSlider) p.control(control)).setValue(value));
    }

    static void click(SettingsPanel p, String control) {
        ViewerFrame.onEdt(() -> ((AbstractButton) p.control(control)).doClick());
    }

    static void press(char key) {
        short code = KeyEvent.utf16ToVKey(key);
        frame.view().controller().keyListener().keyPressed(KeyEvent.create(KeyEvent.EVENT_KEY_PRESSED,
                frame.view().window().glWindow(), System.currentTimeMillis(), 0, code, code, key));
    }

    static com.jogamp.newt.event.MouseEvent newtMouse(short type, int x, int y) {
        return new com.jogamp.newt.event.MouseEvent(type, frame.view().window().glWindow(), System.currentTimeMillis(),
                0, x, y, (short) 1, com.jogamp.newt.event.MouseEvent.BUTTON1, new float[] {0, 0, 0}, 1f);
    }

    /** Hands {@code file} to the frame's drop target as a drag and drop of files does. */
    static boolean drop(TransferHandler target, Path file) {
        Transferable files = new Transferable() {
            @Override
            public DataFlavor[] getTransferDataFlavors() {
                return new DataFlavor[] {DataFlavor.javaFileListFlavor};
            }

            @Override
            public boolean isDataFlavorSupported(DataFlavor flavor) {
                return DataFlavor.javaFileListFlavor.equals(flavor);
            }

            @Override
            public Object getTransferData(DataFlavor flavor) {
                return List.<File>of(file.toFile());
            }
        };
        boolean[] imported = new boolean[1];
        ViewerFrame.onEdt(() -> imported[0] = target.importData(new TransferHandler.TransferSupport(
                frame.frame().getContentPane(), files)));
        return imported[0];
    }

    static Window awaitWindow(String name) throws InterruptedException {
        Window[] found = new Window[1];
        assertTrue(waitFor(() -> {
            for (Window w : Window.getWindows()) {
                if (name.equals(w.getName()) && w.isShowing()) {
                    found[0] = w;
                    return true;
                }
            }
            return false;
        }, 60), "no window " + name);
        return found[0];
    }

    static <T extends Component> T find(Container root, Class<T> type, String name) {
        for (Component c : root.getComponents()) {
            if (type.isInstance(c) && (name == null || name.equals(c.getName()))) {
                return type.cast(c);
            }
            if (c instanceof Container inner) {
                T t = find(inner, type, name);
                if (t != null) {
                    return t;
                }
            }
        }
        return null;
    }

    static JButton findButton(Container root, String text) {
        JButton b = buttonIn(root, text);
        if (b == null) {
            throw new AssertionError("no button " + text);
        }
        return b;
    }

    private static JButton buttonIn(Container root, String text) {
        for (Component c : root.getComponents()) {
            if (c instanceof JButton b && text.equals(b.getText())) {
                return b;
            }
            if (c instanceof Container inner) {
                JButton b = buttonIn(inner, text);
                if (b != null) {
                    return b;
                }
            }
        }
        return null;
    }

    static void awaitState(BooleanSupplier condition, String what) throws InterruptedException {
        assertTrue(waitFor(condition, 120), what + " never reached the state: " + state());
    }

    static void awaitPanel(BooleanSupplier condition, String what) throws InterruptedException {
        boolean[] ok = new boolean[1];
        assertTrue(waitFor(() -> {
            ViewerFrame.onEdt(() -> ok[0] = condition.getAsBoolean());
            return ok[0];
        }, 60), what);
    }

    static void awaitRefined() throws InterruptedException {
        assertTrue(waitFor(() -> frame.view().refinement().isRefined(state()), 300), "never refined: "
                + frame.view().refinement());
    }

    static void assertThrows(org.junit.jupiter.api.function.Executable e) {
        org.junit.jupiter.api.Assertions.assertThrows(java.io.IOException.class, e);
    }

    static boolean waitFor(BooleanSupplier condition, double seconds) throws InterruptedException {
        long end = System.nanoTime() + (long) (seconds * 1e9);
        while (System.nanoTime() < end) {
            if (condition.getAsBoolean()) {
                return true;
            }
            Thread.sleep(20);
        }
        return condition.getAsBoolean();
    }
}
