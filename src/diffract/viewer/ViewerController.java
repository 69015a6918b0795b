package diffract.viewer;

import com.jogamp.newt.event.KeyAdapter;
import com.jogamp.newt.event.KeyEvent;
import com.jogamp.newt.event.MouseAdapter;
import com.jogamp.newt.event.MouseEvent;
import diffract.optics.BrdfSettings;
import diffract.optics.LightPolicy;
import diffract.optics.settings.LightProfile;
import diffract.scene.LightDirection;
import diffract.optics.spectra.TaylorSettings;
import diffract.optics.Variant;
import diffract.scene.DisplayMode;

import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.UnaryOperator;

/**
 * Maps input to the model. The NEWT listeners ({@link #keyListener()}, {@link #mouseListener()}) translate events
 * into the public actions and queue them; the render loop applies the queue, in order, between the tiles it draws
 * ({@link #applyQueuedInput}), so no input is lost however long a frame takes, and a frame never sees half of a
 * burst of input. Quitting runs at once on the input thread. Every action only replaces the model's snapshot or
 * hands work to a background thread (a precompute of more Taylor terms, writing a screenshot), so it never waits.
 * Tests may call the actions directly.
 */
public final class ViewerController implements AutoCloseable {
    /** The lambda steps [ and ] walk through, in nm. */
    static final double[] LAMBDA_STEPS_NM = {1, 2, 5, 10, 20, 40};
    static final double ORBIT_DEG_PER_PX = 0.4;
    static final double LIGHT_DEG_PER_PX = 0.3;
    static final double ZOOM_PER_WHEEL_STEP = 0.9;
    static final double EXPOSURE_STEP = 1.5;
    /** How long a notice about a key stays in the title. */
    static final double NOTICE_SECONDS = 6;

    /** Takes a screenshot of the real window and returns where it went (run off the input thread). */
    @FunctionalInterface
    public interface Screenshotter {
        Path save() throws IOException;
    }

    private final ViewerModel model;
    private final TermPrecomputer precomputer;
    private final Screenshotter screenshotter;
    private final Runnable quit;
    private final BlockingQueue<Consumer<ViewerController>> queued = new LinkedBlockingQueue<>();
    private final ExecutorService screenshotWriter = Executors.newSingleThreadExecutor(runnable -> {
        Thread thread = new Thread(runnable, "diffract-viewer-screenshot");
        thread.setDaemon(true);
        return thread;
    });

    public ViewerController(ViewerModel model, TermPrecomputer precomputer, Screenshotter screenshotter,
                            Runnable quit) {
        this.model = model;
        this.precomputer = precomputer;
        this.screenshotter = screenshotter;
        this.quit = quit;
    }

    // ---- actions

    private void updateView(UnaryOperator<ViewerState.View> change) {
        model.update(s -> s.withView(change.apply(s.view())));
    }

    public void orbitByPixels(int dxPx, int dyPx) {
        // dragging right turns the object to the right: the camera moves left around it
        updateView(v -> v.withCamera(v.camera().orbitedBy(-dxPx * ORBIT_DEG_PER_PX, dyPx * ORBIT_DEG_PER_PX)));
    }

    /** Positive steps (wheel up) zoom in. */
    public void zoomBySteps(double steps) {
        updateView(v -> v.withCamera(v.camera().zoomedBy(Math.pow(ZOOM_PER_WHEEL_STEP, steps))));
    }

    public void moveLightByPixels(int dxPx, int dyPx) {
        updateView(v -> v.withLight(v.light().movedBy(dyPx * LIGHT_DEG_PER_PX, dxPx * LIGHT_DEG_PER_PX)));
    }

    public void moveLightBy(double deltaThetaDeg, double deltaPhiDeg) {
        updateView(v -> v.withLight(v.light().movedBy(deltaThetaDeg, deltaPhiDeg)));
    }

    /** The variant; one that cannot take the scene's light draws it as a point light and says so. */
    public void selectVariant(Variant variant) {
        model.update(s -> {
            ViewerState selected = s.withSettings(s.settings().with(b -> b.drawnBy(variant)));
            return LightPolicy.of(selected.settings()).notice()
                    .map(text -> selected.withNotice(Notice.forSeconds(text, NOTICE_SECONDS))).orElse(selected);
        });
    }

    /** N + delta within [0, {@link TaylorSettings#MAX_HIGHEST_ORDER}]; more terms than at hand start a background precompute. */
    public void changeTaylorOrderBy(int delta) {
        ViewerState state = model.update(s -> s.withSettings(s.settings().with(b -> b.highestOrder(Math.max(0,
                Math.min(TaylorSettings.MAX_HIGHEST_ORDER, s.settings().taylor().highestOrder() + delta))))));
        precomputer.ensureTermsFor(state);
    }

    /** One rung up (+1) or down (-1) the lambda-step ladder. */
    public void changeLambdaStep(int direction) {
        model.update(s -> s.withSettings(s.settings().with(b -> b.lambdaStepNm(nextLambdaStep(s.settings(), direction)))));
    }

    static double nextLambdaStep(BrdfSettings settings, int direction) {
        double current = settings.spectral().lambdaStepNm();
        if (direction > 0) {
            for (double step : LAMBDA_STEPS_NM) {
                if (step > current + 1e-9) {
                    return step;
                }
            }
            return current;
        }
        for (int i = LAMBDA_STEPS_NM.length - 1; i >= 0; i--) {
            if (LAMBDA_STEPS_NM[i] < current - 1e-9) {
                return LAMBDA_STEPS_NM[i];
            }
        }
        return current;
    }

    public void changeExposure(int direction) {
        updateView(v -> v.withExposure(v.exposure() * Math.pow(EXPOSURE_STEP, direction)));
    }

    public void toggleBrdfMap() {
        updateView(v -> v.withMode(v.mode() == DisplayMode.BRDF_MAP ? DisplayMode.SURFACE : DisplayMode.BRDF_MAP));
    }

    public void togglePigmentation() {
        if (model.pigmentationImage().isEmpty()) {
            model.update(s -> s.withNotice(Notice.forSeconds("no pigmentation image: give the scene one, or start "
                    + "with a pigmentation image", 4)));
            return;
        }
        updateView(v -> v.withPigmentationOn(!v.pigmentationOn()));
    }

    // ---- the frame's controls: each sets one value, as the keys change one; settings a method refuses are said

    /** The light at (theta_i, phi_i) in degrees (theta_i kept within LightDirection's range). */
    public void setLight(double thetaDeg, double phiDeg) {
        updateView(v -> v.withLight(new LightDirection(thetaDeg, phiDeg)));
    }

    /** N; more terms than at hand start a background precompute. */
    public void setTaylorOrder(int n) {
        changeSettings(b -> b.highestOrder(n)).ifPresent(precomputer::ensureTermsFor);
    }

    public void setLambdaStep(double stepNm) {
        changeSettings(b -> b.lambdaStepNm(stepNm));
    }

    public void setCoherenceLength(double um) {
        changeSettings(b -> b.coherenceLengthUm(um));
    }

    /** The light's angular diameter; a method that cannot take it draws a point light and says so. */
    public void setLightSize(double diameterDeg) {
        changeSettings(b -> b.lightSizeDeg(diameterDeg)).ifPresent(this::noticeLightPolicy);
    }

    public void setLightProfile(LightProfile profile) {
        changeSettings(b -> b.lightProfile(profile));
    }

    /** The window radius R, or with {@code radius} null the automatic one. */
    public void setWindowRadius(Integer radius) {
        changeSettings(b -> {
            if (radius == null) {
                b.automaticWindowRadius(true);
            } else {
                b.automaticWindowRadius(false).windowRadius(radius);
            }
        });
    }

    public void setExposure(double exposure) {
        if (exposure > 0 && Double.isFinite(exposure)) {
            updateView(v -> v.withExposure(exposure));
        }
    }

    public void setPigmentation(boolean on) {
        if (on && model.pigmentationImage().isEmpty()) {
            togglePigmentation(); // says there is none
            return;
        }
        updateView(v -> v.withPigmentationOn(on));
    }

    public void setMode(DisplayMode mode) {
        updateView(v -> v.withMode(mode));
    }

    /** An A/B split of the picture ({@code null}: off); B's light as the light policy draws it, said. */
    public void setSplit(ViewerState.Split split) {
        updateView(v -> v.withSplit(split));
        if (split != null) {
            LightPolicy.of(split.other()).notice().ifPresent(text -> model.update(s -> s.withNotice(
                    Notice.forSeconds("B: " + text, NOTICE_SECONDS))));
        }
    }

    /** Moves the split's divider (a fraction of the picture's width); nothing without a split. */
    public void setSplitDivider(double divider) {
        updateView(v -> v.split() == null ? v : v.withSplit(v.split().withDivider(divider)));
    }

    /**
     * The settings changed by {@code change}: the new state, or empty with a notice when the settings refuse the value
     * (its range, said as the settings say it).
     */
    private java.util.Optional<ViewerState> changeSettings(java.util.function.Consumer<BrdfSettings.Builder> change) {
        try {
            return java.util.Optional.of(model.update(s -> s.withSettings(s.settings().with(change))));
        } catch (diffract.optics.settings.InvalidSettingException | IllegalArgumentException e) {
            model.update(s -> s.withNotice(Notice.forSeconds(e.getMessage(), NOTICE_SECONDS)));
            return java.util.Optional.empty();
        }
    }

    private void noticeLightPolicy(ViewerState state) {
        LightPolicy.of(state.settings()).notice().ifPresent(text -> model.update(s -> s.withNotice(
                Notice.forSeconds(text, NOTICE_SECONDS))));
    }

    public void reset() {
        model.reset(Notice.forSeconds("reset", 2));
    }

    /** Prints the controls and shows them in the title for a few seconds. */
    public void showHelp() {
        System.out.print(KeyBindings.helpText());
        System.out.flush();
        model.update(s -> s.withNotice(Notice.forSeconds(KeyBindings.oneLine(), 8)));
    }

    /** Saves a PNG of the window on a background thread; the path is printed and shown in the title. */
    public Future<Path> screenshot() {
        return screenshotWriter.submit(() -> {
            try {
                Path file = screenshotter.save();
                System.out.println("screenshot: " + file.toAbsolutePath());
                model.update(s -> s.withNotice(Notice.forSeconds("saved " + file, 4)));
                return file;
            } catch (IOException | RuntimeException e) {
                System.err.println("diffract: screenshot failed: " + e.getMessage());
                model.update(s -> s.withNotice(Notice.forSeconds("screenshot failed: " + e.getMessage(), 6)));
                throw e;
            }
        });
    }

    public void quit() {
        quit.run();
    }

    // ---- the input queue

    /** Queues an action for the render loop ({@link #applyQueuedInput}). */
    public void queue(Consumer<ViewerController> action) {
        queued.add(action);
    }

    /**
     * Applies the queued actions, in order, on the calling thread (the render loop's); first waits up to
     * {@code waitMs} for one if none is queued. Returns how many were applied.
     */
    public int applyQueuedInput(long waitMs) throws InterruptedException {
        Consumer<ViewerController> action = waitMs > 0 ? queued.poll(waitMs, TimeUnit.MILLISECONDS) : queued.poll();
        int applied = 0;
        for (; action != null; action = queued.poll()) {
            action.accept(this);
            applied++;
        }
        return applied;
    }

    /** Actions queued and not yet applied. */
    public int queuedInput() {
        return queued.size();
    }

    // ---- NEWT input

    /** Keys as in {@link KeyBindings}. */
    public KeyAdapter keyListener() {
        return new KeyAdapter() {
            @Override
            public void keyPressed(KeyEvent e) {
                handleKey(e.getKeyCode(), e.getKeyChar());
            }
        };
    }

    /**
     * Dispatches one key press through {@link KeyBindings#ALL}: queues its action, or runs it now if it is
     * immediate; returns whether it was a control.
     */
    boolean handleKey(short keyCode, char keyChar) {
        KeyBindings.Trigger trigger = KeyBindings.triggerFor(keyCode, keyChar);
        if (trigger == null) {
            return false;
        }
        if (trigger.immediate()) {
            trigger.action().accept(this);
        } else {
            queue(trigger.action());
        }
        return true;
    }

    /** How near the A/B split's divider a left drag takes it instead of orbiting, in window pixels. */
    static final int DIVIDER_GRAB_PX = 6;

    /** The width of the window an event came from (0 when it is not a window's). */
    private static int widthOf(MouseEvent e) {
        return e.getSource() instanceof com.jogamp.newt.Window w ? w.getSurfaceWidth() : 0;
    }

    /**
     * Left drag orbits (or, started on an A/B split's divider, moves it), right drag moves the light, the wheel zooms
     * (queued, as keys are).
     */
    public MouseAdapter mouseListener() {
        return new MouseAdapter() {
            private int lastX;
            private int lastY;
            private short button;

            private boolean onDivider;

            @Override
            public void mousePressed(MouseEvent e) {
                lastX = e.getX();
                lastY = e.getY();
                button = e.getButton();
                int width = widthOf(e);
                ViewerState.Split split = model.state().view().split();
                onDivider = button == MouseEvent.BUTTON1 && split != null && width > 0
                        && Math.abs(e.getX() - split.divider() * width) <= DIVIDER_GRAB_PX;
            }

            @Override
            public void mouseDragged(MouseEvent e) {
                int dx = e.getX() - lastX;
                int dy = e.getY() - lastY;
                lastX = e.getX();
                lastY = e.getY();
                int width = widthOf(e);
                if (onDivider && width > 0) {
                    double divider = e.getX() / (double) width;
                    queue(c -> c.setSplitDivider(divider));
                } else if (button == MouseEvent.BUTTON3) {
                    queue(c -> c.moveLightByPixels(dx, dy));
                } else {
                    queue(c -> c.orbitByPixels(dx, dy));
                }
            }

            @Override
            public void mouseWheelMoved(MouseEvent e) {
                float[] rotation = e.getRotation();
                float steps = rotation[1] != 0 ? rotation[1] : rotation[0]; // shift turns NEWT's wheel sideways
                queue(c -> c.zoomBySteps(steps));
            }
        };
    }

    @Override
    public void close() {
        screenshotWriter.shutdown();
    }
}
