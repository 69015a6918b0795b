package diffract.viewer;

import com.jogamp.nativewindow.WindowClosingProtocol;
import com.jogamp.newt.event.WindowAdapter;
import com.jogamp.newt.event.WindowEvent;
import diffract.jrtr.contexts.OnscreenWindow;
import diffract.util.ImageFiles;

import java.io.IOException;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * The view: a jrtr window drawn by a render loop of its own, the controller attached to its input, and the title
 * kept up to date by a timer thread. The loop ("diffract-viewer-render") applies the queued input, then lets the
 * {@link RefiningRenderer} draw one tile and show the picture, and waits for input while the picture is refined
 * and nothing changes; a tile takes about {@value RefiningRenderer#TILE_MS} ms, so input is applied and a quit
 * noticed within about that long however expensive the frame. The title (variant, parameters, light, the
 * refinement's stage, ms/frame, background work) is set by the timer, so neither the render thread nor the input
 * thread ever waits for it.
 */
public final class ViewerWindow implements AutoCloseable {
    static final long TITLE_PERIOD_MS = 250;
    /** The render loop looks at the model this often while it has nothing to draw (background work changes it). */
    static final long IDLE_WAIT_MS = 50;
    /** How long closing waits for the render loop to finish its tile. */
    static final long CLOSE_WAIT_MS = 10_000;
    /** How long a read of the window waits for the render loop to show the picture (a busy machine is slow). */
    static final long READ_WAIT_MS = 60_000;
    private static final DateTimeFormatter SCREENSHOT_TIME = DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss-SSS");

    private final ViewerModel model;
    private final ViewerRenderer renderer;
    private final RefiningRenderer refiner;
    private final OnscreenWindow window;
    private final TermPrecomputer precomputer;
    private final TableBaker baker;
    private final ViewerController controller;
    private final Path screenshotDir;
    private final CountDownLatch closeRequested = new CountDownLatch(1);
    private final ScheduledExecutorService titleUpdater = Executors.newSingleThreadScheduledExecutor(runnable -> {
        Thread thread = new Thread(runnable, "diffract-viewer-title");
        thread.setDaemon(true);
        return thread;
    });
    private final Thread renderLoop = new Thread(this::renderLoop, "diffract-viewer-render");
    private volatile boolean stopping;
    private volatile String shownTitle = "";
    /** Where the title line goes when the window is embedded in a frame, else null (the window's own title). */
    private final java.util.function.Consumer<String> titleSink;

    /** Opens the window (drawing starts with {@link #start}); throws UserInputException when there is no display. */
    public ViewerWindow(ViewerModel model, int widthPx, int heightPx, Path screenshotDir) {
        this(model, widthPx, heightPx, screenshotDir, null);
    }

    /**
     * With {@code titleSink} null, a window of its own (as above); else a window to embed in a frame
     * ({@link #window()}{@code .canvas()}), whose title line goes to {@code titleSink} (called on the title's timer).
     */
    public ViewerWindow(ViewerModel model, int widthPx, int heightPx, Path screenshotDir,
                        java.util.function.Consumer<String> titleSink) {
        this.model = model;
        this.screenshotDir = screenshotDir;
        this.titleSink = titleSink;
        this.renderer = new ViewerRenderer(model);
        this.baker = new TableBaker(model);
        this.refiner = new RefiningRenderer(model, renderer, baker);
        refiner.drawOn(renderLoop);
        this.window = titleSink == null ? new OnscreenWindow("diffract viewer", widthPx, heightPx, refiner)
                : OnscreenWindow.embedded(refiner, widthPx, heightPx);
        this.precomputer = new TermPrecomputer(model);
        this.controller = new ViewerController(model, precomputer, this::saveScreenshot, closeRequested::countDown);
        window.glWindow().addKeyListener(controller.keyListener());
        window.glWindow().addMouseListener(controller.mouseListener());
        if (titleSink == null) {
            // the close button only asks to quit: the window is destroyed by close(), after the render loop stopped
            window.glWindow().setDefaultCloseOperation(WindowClosingProtocol.WindowClosingMode.DO_NOTHING_ON_CLOSE);
            window.glWindow().addWindowListener(new WindowAdapter() {
                @Override
                public void windowDestroyNotify(WindowEvent e) {
                    closeRequested.countDown();
                }
            });
        }
        renderLoop.setDaemon(true);
    }

    /** Starts the render loop, the title updates, and a precompute if the setup asks for more terms. */
    public void start() {
        renderLoop.start();
        titleUpdater.scheduleAtFixedRate(this::updateTitle, 0, TITLE_PERIOD_MS, TimeUnit.MILLISECONDS);
        precomputer.ensureTermsFor(model.state());
    }

    private void renderLoop() {
        try {
            while (!stopping && !isCloseRequested()) {
                controller.applyQueuedInput(0);
                if (refiner.needsDisplay()) {
                    window.display();
                } else {
                    controller.applyQueuedInput(IDLE_WAIT_MS);
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (RuntimeException e) {
            System.err.println("diffract: the viewer stopped drawing: " + e.getMessage());
            closeRequested.countDown();
        }
    }

    /** Blocks until the user quits (Esc, Q or the window's close button). */
    public void awaitCloseRequest() throws InterruptedException {
        closeRequested.await();
    }

    public boolean isCloseRequested() {
        return closeRequested.getCount() == 0;
    }

    /** Whether the render loop still runs (it stops at a quit, after the tile under way). */
    public boolean isDrawing() {
        return renderLoop.isAlive();
    }

    public ViewerController controller() {
        return controller;
    }

    public ViewerRenderer renderer() {
        return renderer;
    }

    public ViewerModel model() {
        return model;
    }

    /** The background bake of the baked table (the frame's status bar reads whether one is under way). */
    public TableBaker baker() {
        return baker;
    }

    /** Holds the last pass of each refinement after its first tile ({@link RefiningRenderer#holdLastPass}): tests. */
    void holdLastPass(boolean hold) {
        refiner.holdLastPass(hold);
    }

    /** Where the refinement of the picture stands. */
    public RefinementStatus refinement() {
        return refiner.status();
    }

    public OnscreenWindow window() {
        return window;
    }

    /** The title as last set (the timer sets it when it changes). */
    public String title() {
        return shownTitle;
    }

    private void updateTitle() {
        try {
            String title = ViewerTitle.of(model, model.state(), renderer.stats(), refiner.status(), System.nanoTime());
            if (!title.equals(shownTitle)) {
                if (titleSink != null) {
                    titleSink.accept(title);
                } else {
                    window.setTitle(title);
                }
                shownTitle = title;
            }
        } catch (RuntimeException e) {
            // a title that fails to update must not stop the timer (the exception would cancel it)
            System.err.println("diffract: title update failed: " + e);
        }
    }

    /**
     * What the window shows, and where the refinement stood then: read by the render loop after it next shows the
     * picture. Blocks until then: call it off the input and render threads.
     */
    public RefiningRenderer.Shown shown() {
        try {
            return refiner.readBack().get(READ_WAIT_MS, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while reading the window", e);
        } catch (ExecutionException | TimeoutException e) {
            throw new IllegalStateException("the window was not read: " + e.getMessage(), e);
        }
    }

    /** Writes what the window shows as a PNG of its size into the screenshot folder (call it off the input thread). */
    public Path saveScreenshot() throws IOException {
        RefiningRenderer.Shown shown = shown();
        float[] rgba = shown.rgba();
        int width = shown.width();
        int height = shown.height();
        float[] rgb = new float[width * height * 3];
        for (int p = 0; p < width * height; p++) {
            System.arraycopy(rgba, 4 * p, rgb, 3 * p, 3);
        }
        Path file = screenshotDir.resolve("diffract-viewer-" + LocalDateTime.now().format(SCREENSHOT_TIME) + ".png");
        ImageFiles.writePng(file, rgb, width, height, 3);
        return file;
    }

    /** Stops the render loop (after the tile under way), the background work and the title, then the window. */
    @Override
    public void close() {
        titleUpdater.shutdownNow();
        stopping = true;
        controller.queue(c -> { }); // wakes a loop waiting for input
        try {
            if (renderLoop.isAlive()) {
                renderLoop.join(CLOSE_WAIT_MS);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        controller.close();
        precomputer.close();
        baker.close();
        window.close();
    }
}
