package diffract.viewer;

import com.jogamp.newt.event.WindowAdapter;
import com.jogamp.newt.event.WindowEvent;
import diffract.jrtr.OnscreenWindow;
import diffract.util.ImageFiles;

import java.io.IOException;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * The view: a jrtr window drawing the model with a {@link ViewerRenderer} continuously, the controller attached to
 * its input, and the title kept up to date (variant, parameters, light, ms/frame, precompute progress) by a timer
 * thread, so neither the render thread nor the input thread ever waits for the title.
 */
public final class ViewerWindow implements AutoCloseable {
    static final long TITLE_PERIOD_MS = 250;
    private static final DateTimeFormatter SCREENSHOT_TIME = DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss-SSS");

    private final ViewerModel model;
    private final ViewerRenderer renderer;
    private final OnscreenWindow window;
    private final TermPrecomputer precomputer;
    private final ViewerController controller;
    private final Path screenshotDir;
    private final CountDownLatch closeRequested = new CountDownLatch(1);
    private final ScheduledExecutorService titleUpdater = Executors.newSingleThreadScheduledExecutor(runnable -> {
        Thread thread = new Thread(runnable, "diffract-viewer-title");
        thread.setDaemon(true);
        return thread;
    });
    private volatile String shownTitle = "";

    /** Opens the window (not yet animating); throws UserInputException when there is no display. */
    public ViewerWindow(ViewerModel model, int widthPx, int heightPx, Path screenshotDir) {
        this.model = model;
        this.screenshotDir = screenshotDir;
        this.renderer = new ViewerRenderer(model);
        this.window = new OnscreenWindow("diffract viewer", widthPx, heightPx, renderer);
        this.precomputer = new TermPrecomputer(model);
        this.controller = new ViewerController(model, precomputer, this::saveScreenshot, closeRequested::countDown);
        window.glWindow().addKeyListener(controller.keyListener());
        window.glWindow().addMouseListener(controller.mouseListener());
        window.glWindow().addWindowListener(new WindowAdapter() {
            @Override
            public void windowDestroyNotify(WindowEvent e) {
                closeRequested.countDown(); // the window's close button
            }
        });
    }

    /** Starts drawing continuously, the title updates, and a precompute if the setup asks for more terms. */
    public void start() {
        window.startAnimation();
        titleUpdater.scheduleAtFixedRate(this::updateTitle, 0, TITLE_PERIOD_MS, TimeUnit.MILLISECONDS);
        precomputer.ensureTermsFor(model.state());
    }

    /** Blocks until the user quits (Esc, Q or the window's close button). */
    public void awaitCloseRequest() throws InterruptedException {
        closeRequested.await();
    }

    public boolean isCloseRequested() {
        return closeRequested.getCount() == 0;
    }

    public ViewerController controller() {
        return controller;
    }

    public ViewerRenderer renderer() {
        return renderer;
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
            String title = ViewerTitle.of(model, model.state(), renderer.stats(), System.nanoTime());
            if (!title.equals(shownTitle)) {
                window.setTitle(title);
                shownTitle = title;
            }
        } catch (RuntimeException e) {
            // a title that fails to update must not stop the timer (the exception would cancel it)
            System.err.println("diffract: title update failed: " + e);
        }
    }

    /**
     * Reads what the window shows (glReadPixels of the back buffer after a frame) and writes it as a PNG of the
     * window's size into the screenshot folder. Blocks until the next frame is drawn: call it off the input thread.
     */
    public Path saveScreenshot() throws IOException {
        float[] rgba = window.renderRgba();
        int width = window.surfaceWidth();
        int height = window.surfaceHeight();
        float[] rgb = new float[width * height * 3];
        for (int p = 0; p < width * height; p++) {
            System.arraycopy(rgba, 4 * p, rgb, 3 * p, 3);
        }
        Path file = screenshotDir.resolve("diffract-viewer-" + LocalDateTime.now().format(SCREENSHOT_TIME) + ".png");
        ImageFiles.writePng(file, rgb, width, height, 3);
        return file;
    }

    @Override
    public void close() {
        titleUpdater.shutdownNow();
        controller.close();
        precomputer.close();
        try {
            renderer.stopDrawing(30_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        window.close();
    }
}
