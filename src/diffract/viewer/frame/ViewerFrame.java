package diffract.viewer.frame;

import diffract.render.FrameOutput;
import diffract.scene.Fabricator;
import diffract.scene.Scene;
import diffract.scene.SceneFile;
import diffract.scene.SceneSetup;
import diffract.scene.SceneWriter;
import diffract.util.ImageFiles;
import diffract.util.OpenExr;
import diffract.util.Reporter;
import diffract.viewer.Notice;
import diffract.viewer.ViewerModel;
import diffract.viewer.ViewerRenderer;
import diffract.viewer.ViewerWindow;

import javax.swing.BorderFactory;
import javax.swing.BoxLayout;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import javax.swing.TransferHandler;
import javax.swing.filechooser.FileNameExtensionFilter;
import java.awt.BorderLayout;
import java.awt.Component;
import java.awt.Dimension;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.datatransfer.DataFlavor;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.function.BiFunction;

/**
 * The viewer as a Swing frame, as jrtr's was: the GL view in the middle (the {@link ViewerWindow}'s NEWT window in an
 * AWT canvas: its render loop, refinement and keys as in a window of its own), the settings that matter beside it
 * ({@link SettingsPanel}, each applied through the same input queue and refinement as the keys), the light on a
 * hemisphere ({@link LightWidget}), the BRDF map of the current light ({@link MapInset}), the current method against
 * the exact reference ({@link ReferencePanel}), and a status bar with the refinement's, the bake's and the precompute's
 * progress and the frame time ({@link StatusBar}). Files: open a scan or a scene (menu, drag and drop; a .gwy's or
 * .ibw's channels to choose from, {@link ScanDialog}), save the picture (PNG, or OpenEXR as linear light) and the scene
 * that draws it again ({@link ViewScene}), recent files ({@link RecentFiles}).
 *
 * <p>Opening a file builds the new scene in the background (the status bar says so) and then replaces the view: the
 * old window's render loop stops, a new one starts on the new model. The panels read the model's state on a Swing
 * timer; nothing on the event thread waits for the GL.
 */
public final class ViewerFrame implements AutoCloseable {
    /** How often the panels read the state. */
    static final int REFRESH_MS = 150;
    /** {@link #REFRESH_MS}, for callers that wait for the panels to show a change. */
    public static int refreshMs() {
        return REFRESH_MS;
    }

    /** The side panel's width. */
    static final int SIDE_WIDTH_PX = 350;

    private final JFrame frame;
    private final JPanel viewHolder = new JPanel(new BorderLayout());
    private final SettingsPanel settings;
    private final LightWidget lightWidget;
    private final MapInset inset;
    private final ReferencePanel reference;
    private final StatusBar status = new StatusBar();
    private final RecentFiles recent;
    private final JMenu recentMenu = new JMenu("Recent files");
    private final Path screenshotDir;
    private final BiFunction<Scene, Scene.ShapeKind, Scene> shapeChange;
    private final Reporter reporter;
    private final CountDownLatch closeRequested = new CountDownLatch(1);
    private final ExecutorService loader = diffract.util.BackgroundThreads.single("diffract-viewer-open");
    private final Timer refresh;
    private volatile ViewerWindow view;
    private volatile Scene scene;
    private volatile CompletableFuture<Void> opening = CompletableFuture.completedFuture(null);

    /**
     * Opens the frame on {@code model}, drawn from {@code scene} (what a saved scene starts from).
     *
     * @param shapeChange the scene with another shape (the app knows the shipped snake's scene); null: fixed shape
     * @param recent      where the recent files are kept
     */
    public ViewerFrame(Scene scene, ViewerModel model, int widthPx, int heightPx, Path screenshotDir,
                       BiFunction<Scene, Scene.ShapeKind, Scene> shapeChange, RecentFiles recent, Reporter reporter) {
        this.scene = scene;
        this.screenshotDir = screenshotDir;
        this.shapeChange = shapeChange;
        this.recent = recent;
        this.reporter = reporter;
        this.settings = new SettingsPanel(this::view, this::changeShape);
        this.lightWidget = new LightWidget(this::view);
        this.inset = new MapInset();
        this.reference = new ReferencePanel(this::view);
        ViewerFrame[] self = {this};
        JFrame[] made = new JFrame[1];
        onEdt(() -> made[0] = new JFrame("diffract viewer"));
        this.frame = made[0];
        onEdt(() -> build(widthPx, heightPx));
        install(new ViewerWindow(model, widthPx, heightPx, screenshotDir, this::titleChanged));
        this.refresh = new Timer(REFRESH_MS, e -> self[0].refreshPanels());
        refresh.start();
    }

    private void build(int widthPx, int heightPx) {
        frame.setDefaultCloseOperation(JFrame.DO_NOTHING_ON_CLOSE);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                closeRequested.countDown();
            }
        });
        frame.setJMenuBar(menus());
        // left of the view the light and the BRDF map of the light, as the BRDF explorers place them; right of it the
        // settings and the comparison with the reference
        JPanel left = new JPanel();
        left.setLayout(new BoxLayout(left, BoxLayout.Y_AXIS));
        for (JComponent c : List.of(lightWidget.titled(), inset.titled())) {
            c.setAlignmentX(Component.LEFT_ALIGNMENT);
            left.add(c);
        }
        left.add(javax.swing.Box.createVerticalGlue());
        JPanel side = new WidthTracking();
        side.setLayout(new BoxLayout(side, BoxLayout.Y_AXIS));
        for (JComponent c : List.of(settings, reference)) {
            c.setAlignmentX(Component.LEFT_ALIGNMENT);
            side.add(c);
        }
        JScrollPane sideScroll = new JScrollPane(side, JScrollPane.VERTICAL_SCROLLBAR_AS_NEEDED,
                JScrollPane.HORIZONTAL_SCROLLBAR_NEVER);
        sideScroll.setPreferredSize(new Dimension(SIDE_WIDTH_PX, heightPx));
        sideScroll.setBorder(BorderFactory.createEmptyBorder());
        sideScroll.getVerticalScrollBar().setUnitIncrement(16);
        viewHolder.setPreferredSize(new Dimension(widthPx, heightPx));
        frame.getContentPane().add(left, BorderLayout.WEST);
        frame.getContentPane().add(viewHolder, BorderLayout.CENTER);
        frame.getContentPane().add(sideScroll, BorderLayout.EAST);
        frame.getContentPane().add(status, BorderLayout.SOUTH);
        TransferHandler drop = new FileDrop(this::openDropped);
        frame.setTransferHandler(drop);
        viewHolder.setTransferHandler(drop);
        side.setTransferHandler(drop);
        left.setTransferHandler(drop);
        frame.pack();
        frame.setVisible(true);
    }

    private JMenuBar menus() {
        JMenuBar bar = new JMenuBar();
        JMenu file = new JMenu("File");
        file.add(item("Open scan...", KeyEvent.VK_O, e -> chooseScan()));
        file.add(item("Open scene...", 0, e -> chooseScene()));
        file.add(recentMenu);
        file.addSeparator();
        file.add(item("Save picture...", 0, e -> choosePicture()));
        file.add(item("Save scene...", 0, e -> chooseSceneFile()));
        file.addSeparator();
        file.add(item("Quit", 0, e -> closeRequested.countDown()));
        bar.add(file);
        fillRecentMenu();
        return bar;
    }

    private static JMenuItem item(String text, int key, java.awt.event.ActionListener action) {
        JMenuItem item = new JMenuItem(text);
        if (key != 0) {
            item.setAccelerator(KeyStroke.getKeyStroke(key, InputEvent.CTRL_DOWN_MASK));
        }
        item.addActionListener(action);
        return item;
    }

    private void fillRecentMenu() {
        recentMenu.removeAll();
        List<Path> files = recent.list();
        for (Path p : files) {
            JMenuItem item = new JMenuItem(p.getFileName() + "  (" + p.getParent() + ")");
            item.addActionListener(e -> openDropped(List.of(p)));
            recentMenu.add(item);
        }
        recentMenu.setEnabled(!files.isEmpty());
    }

    // ---- the view

    /** The view shown now (replaced when a file is opened). */
    public ViewerWindow view() {
        return view;
    }

    /** The scene the view draws, as it was opened (the view's state changes it when saved: {@link ViewScene}). */
    public Scene scene() {
        return scene;
    }

    /** Replaces the view by {@code next}, on the event thread, and starts it. */
    private void install(ViewerWindow next) {
        ViewerWindow previous = view;
        onEdt(() -> {
            viewHolder.removeAll();
            viewHolder.add(next.window().canvas(), BorderLayout.CENTER);
            viewHolder.revalidate();
            frame.validate();
        });
        view = next;
        if (previous != null) {
            previous.close();
        }
        next.start();
        inset.follow(next.model());
    }

    private void titleChanged(String title) {
        SwingUtilities.invokeLater(() -> frame.setTitle(title));
    }

    private void refreshPanels() {
        ViewerWindow v = view;
        if (v == null) {
            return;
        }
        var state = v.model().state();
        settings.refresh(state, scene, shapeChange != null);
        lightWidget.refresh(state);
        if (v.refinement().passesCompleted() > 0) {
            inset.refresh(state); // after the view's first picture: its own draw would compete with it for the GL
        }
        reference.refresh(state);
        status.refresh(state, v.refinement(), v.renderer().stats(), opening.isDone() ? null : "opening");
        if (v.isCloseRequested()) {
            closeRequested.countDown();
        }
    }

    // ---- files

    private void chooseScan() {
        JFileChooser chooser = chooser();
        chooser.setFileFilter(new FileNameExtensionFilter("height fields (.gwy .ibw .gsf .png .bmp .tif .txt)",
                "gwy", "ibw", "gsf", "png", "bmp", "tif", "tiff", "txt", "csv"));
        if (chooser.showOpenDialog(frame) == JFileChooser.APPROVE_OPTION) {
            openScanInteractively(chooser.getSelectedFile().toPath());
        }
    }

    private void chooseScene() {
        JFileChooser chooser = chooser();
        chooser.setFileFilter(new FileNameExtensionFilter("scene files (.json)", "json"));
        if (chooser.showOpenDialog(frame) == JFileChooser.APPROVE_OPTION) {
            openScene(chooser.getSelectedFile().toPath());
        }
    }

    private void choosePicture() {
        JFileChooser chooser = chooser();
        chooser.setSelectedFile(new File("diffract-view.png"));
        if (chooser.showSaveDialog(frame) == JFileChooser.APPROVE_OPTION) {
            savePictureReporting(chooser.getSelectedFile().toPath());
        }
    }

    private void chooseSceneFile() {
        JFileChooser chooser = chooser();
        chooser.setSelectedFile(new File("diffract-view.json"));
        if (chooser.showSaveDialog(frame) == JFileChooser.APPROVE_OPTION) {
            saveSceneReporting(chooser.getSelectedFile().toPath());
        }
    }

    private JFileChooser chooser() {
        List<Path> files = recent.list();
        return new JFileChooser(files.isEmpty() ? new File(".") : files.get(0).toAbsolutePath().getParent().toFile());
    }

    /** Files dropped on the frame (or picked from the recent ones): a .json is a scene, anything else a scan. */
    void openDropped(List<Path> files) {
        if (files.isEmpty()) {
            return;
        }
        Path file = files.get(0);
        if (file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".json")) {
            openScene(file);
        } else {
            openScanInteractively(file);
        }
    }

    /** A scan: its channel (and for an image its sizes) asked in a dialog where the file needs them, then opened. */
    private void openScanInteractively(Path file) {
        ScanDialog.ask(frame, file, reporter).ifPresent(this::openScan);
    }

    /** Opens a scan on the current scene's shape and settings, in the background; returns when it is shown. */
    public CompletableFuture<Void> openScan(Scene.FilePatch patch) {
        Scene base = scene;
        Scene next = base.withMaterial(new Scene.MaterialSpec(patch, view.model().state().settings(), null,
                base.material().pigmentation(), view.model().state().view().pigmentationOn(),
                base.material().diffuseWeight(), view.model().state().view().exposure()));
        return open(ViewScene.of(next, view.model().state(), canvasSize()).withMaterial(next.material()),
                patch.file());
    }

    /** Opens a scene file in the background; returns when it is shown. */
    public CompletableFuture<Void> openScene(Path file) {
        CompletableFuture<Void> done = new CompletableFuture<>();
        try {
            return open(SceneFile.load(file), file);
        } catch (RuntimeException e) {
            said("cannot open " + file + ": " + e.getMessage());
            done.completeExceptionally(e);
            return done;
        }
    }

    /** The current scene with another shape (the app's {@code shapeChange}), opened in the background. */
    private void changeShape(Scene.ShapeKind kind) {
        if (shapeChange == null) {
            return;
        }
        Scene current = ViewScene.of(scene, view.model().state(), canvasSize());
        open(shapeChange.apply(current, kind), null);
    }

    private CompletableFuture<Void> open(Scene next, Path file) {
        CompletableFuture<Void> done = new CompletableFuture<>();
        opening = done;
        status.say("opening " + (file != null ? file.getFileName() : next.shape().kind().sceneName()) + " ...");
        loader.execute(() -> {
            try {
                SceneSetup setup = Fabricator.fabricate(next, reporter);
                ViewerModel model = ViewerModel.load(setup, reporter);
                Dimension size = canvasSize();
                ViewerWindow window = new ViewerWindow(model, size.width, size.height, screenshotDir,
                        this::titleChanged);
                if (file != null) {
                    recent.add(file);
                    SwingUtilities.invokeLater(this::fillRecentMenu);
                }
                scene = next;
                install(window);
                status.say(null);
                done.complete(null);
            } catch (RuntimeException e) {
                said("cannot open " + (file != null ? file : "the scene") + ": " + e.getMessage());
                done.completeExceptionally(e);
            }
        });
        return done;
    }

    /** Says a problem in the view's notice (the status bar shows it) and on standard error. */
    private void said(String text) {
        System.err.println("diffract: " + text);
        status.say(null);
        ViewerWindow v = view;
        if (v != null) {
            v.model().update(s -> s.withNotice(Notice.forSeconds(text, 10)));
        }
    }

    /** The size of the GL view. */
    Dimension canvasSize() {
        Dimension d = viewHolder.getSize();
        return d.width > 0 && d.height > 0 ? d : viewHolder.getPreferredSize();
    }

    /**
     * Saves the picture: a PNG of what the view shows (as the S key), or for {@code .exr} the same view drawn again as
     * linear light (neither tone mapped nor clipped) at the view's size.
     */
    public Path savePicture(Path file) throws IOException {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        ViewerWindow v = view;
        if (name.endsWith(".exr")) {
            ViewerModel copy = new ViewerModel(v.model().setup(), v.model().state().terms());
            copy.update(s -> v.model().state());
            var shown = v.shown();
            try (var target = new diffract.jrtr.OffscreenTarget(new ViewerRenderer(copy, FrameOutput.LINEAR))) {
                float[] rgb = target.renderRgb(shown.width(), shown.height());
                OpenExr.write(file, rgb, shown.width(), shown.height(), 3, OpenExr.Precision.FLOAT,
                        "diffract view: linear sRGB times the exposure, not tone mapped, not clipped");
            }
        } else if (name.endsWith(".png")) {
            var shown = v.shown();
            float[] rgb = new float[shown.width() * shown.height() * 3];
            for (int p = 0; p < shown.width() * shown.height(); p++) {
                System.arraycopy(shown.rgba(), 4 * p, rgb, 3 * p, 3);
            }
            ImageFiles.writePng(file, rgb, shown.width(), shown.height(), 3);
        } else {
            throw new IOException("a picture is saved as .png (what the view shows) or .exr (linear light), not "
                    + file.getFileName());
        }
        return file;
    }

    /** Saves the scene that draws the view's picture again ({@code render FILE} draws it as the view does). */
    public Path saveScene(Path file) throws IOException {
        Scene now = ViewScene.of(scene, view.model().state(), canvasSize());
        Files.writeString(file, SceneWriter.json(now), StandardCharsets.UTF_8);
        recent.add(file);
        SwingUtilities.invokeLater(this::fillRecentMenu);
        return file;
    }

    private void savePictureReporting(Path file) {
        loader.execute(() -> {
            try {
                status.sayFor("saved " + savePicture(file), 4000);
            } catch (IOException | RuntimeException e) {
                said("cannot save " + file + ": " + e.getMessage());
            }
        });
    }

    private void saveSceneReporting(Path file) {
        try {
            status.sayFor("saved " + saveScene(file), 4000);
        } catch (IOException | RuntimeException e) {
            said("cannot save " + file + ": " + e.getMessage());
        }
    }

    /**
     * A screenshot of the whole frame (panels and the GL view) as the screen shows it, into the screenshot folder;
     * for the docs' pictures.
     */
    public Path saveFrameScreenshot() throws Exception {
        Rectangle[] bounds = new Rectangle[1];
        onEdt(() -> bounds[0] = new Rectangle(frame.getLocationOnScreen(), frame.getSize()));
        BufferedImage image = new Robot().createScreenCapture(bounds[0]);
        Files.createDirectories(screenshotDir);
        Path file = screenshotDir.resolve("diffract-frame.png");
        javax.imageio.ImageIO.write(image, "png", file.toFile());
        return file;
    }

    // ---- the panels, for tests

    public SettingsPanel settings() {
        return settings;
    }

    public LightWidget lightWidget() {
        return lightWidget;
    }

    public MapInset inset() {
        return inset;
    }

    public ReferencePanel reference() {
        return reference;
    }

    public StatusBar status() {
        return status;
    }

    public JFrame frame() {
        return frame;
    }

    /** The frame's drop target (what a drag and drop of files onto it hands its files to). */
    public TransferHandler dropTarget() {
        return frame.getTransferHandler();
    }

    /** Blocks until the user quits (Esc, Q, File > Quit or the frame's close button). */
    public void awaitCloseRequest() throws InterruptedException {
        closeRequested.await();
    }

    public boolean isCloseRequested() {
        return closeRequested.getCount() == 0 || view != null && view.isCloseRequested();
    }

    @Override
    public void close() {
        refresh.stop();
        diffract.util.BackgroundThreads.stop(loader);
        inset.close();
        reference.close();
        ViewerWindow v = view;
        if (v != null) {
            v.close();
        }
        onEdt(frame::dispose);
    }

    /** Runs {@code work} on the event thread and waits for it. */
    static void onEdt(Runnable work) {
        if (SwingUtilities.isEventDispatchThread()) {
            work.run();
            return;
        }
        try {
            SwingUtilities.invokeAndWait(work);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (java.lang.reflect.InvocationTargetException e) {
            throw e.getCause() instanceof RuntimeException r ? r : new IllegalStateException(e.getCause());
        }
    }

    /** A panel as wide as its scroll pane's viewport (its rows wrap rather than run out of sight), scrolled up and down. */
    static final class WidthTracking extends JPanel implements javax.swing.Scrollable {
        @Override
        public Dimension getPreferredScrollableViewportSize() {
            return getPreferredSize();
        }

        @Override
        public int getScrollableUnitIncrement(Rectangle visible, int orientation, int direction) {
            return 16;
        }

        @Override
        public int getScrollableBlockIncrement(Rectangle visible, int orientation, int direction) {
            return visible.height - 16;
        }

        @Override
        public boolean getScrollableTracksViewportWidth() {
            return true;
        }

        @Override
        public boolean getScrollableTracksViewportHeight() {
            return false;
        }
    }

    /** Files dropped on the frame: the first one is opened. */
    static final class FileDrop extends TransferHandler {
        private final java.util.function.Consumer<List<Path>> open;

        FileDrop(java.util.function.Consumer<List<Path>> open) {
            this.open = open;
        }

        @Override
        public boolean canImport(TransferSupport support) {
            return support.isDataFlavorSupported(DataFlavor.javaFileListFlavor);
        }

        @Override
        @SuppressWarnings("unchecked")
        public boolean importData(TransferSupport support) {
            if (!canImport(support)) {
                return false;
            }
            try {
                List<File> files = (List<File>) support.getTransferable().getTransferData(
                        DataFlavor.javaFileListFlavor);
                open.accept(files.stream().map(File::toPath).toList());
                return !files.isEmpty();
            } catch (java.awt.datatransfer.UnsupportedFlavorException | IOException e) {
                return false;
            }
        }
    }

    /** An error dialog, for problems the user should not miss. */
    static void showError(Component parent, String text) {
        JOptionPane.showMessageDialog(parent, text, "diffract", JOptionPane.ERROR_MESSAGE);
    }
}
