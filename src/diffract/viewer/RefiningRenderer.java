package diffract.viewer;

import com.jogamp.opengl.GL;
import com.jogamp.opengl.GL3;
import com.jogamp.opengl.GLAutoDrawable;
import com.jogamp.opengl.GLEventListener;
import diffract.jrtr.textures.FloatFramebuffer;
import diffract.jrtr.gl.PixelRect;
import diffract.jrtr.textures.TiledFrame;
import diffract.optics.BrdfSettings;
import diffract.optics.spectra.TaylorTerms;
import diffract.render.GpuMethods;
import diffract.render.ShortPixels;

import diffract.scene.DisplayMode;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Queue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentLinkedQueue;

/**
 * The viewer window's drawing: progressive refinement, as viewport renderers do it. Each change of what the
 * picture shows starts a refinement: a preview ({@link PreviewPolicy}) at 1/8 of the window's resolution, then
 * the configured settings at 1/8, 1/4, 1/2 and the full resolution ({@link #LADDER}), each pass drawn into a
 * framebuffer of its own in tiles of about {@value #TILE_MS} ms ({@link TiledFrame}) and shown, scaled up, the
 * tiles of the pass under way over the last complete pass. A refinement starts at the finest pass estimated to take
 * at most {@value #START_BUDGET_MS} ms (on a fast GPU, the full frame at once), so only a slow machine shows the
 * coarse passes. While the baked variant's table is baked in the background ({@link TableBaker}), the passes draw
 * the preview; the refinement starts again when the table is there.
 *
 * <p>Each {@link #display} call of the render loop ({@link ViewerWindow}) draws a tile (a few if they are quick)
 * and shows the result, so the loop reads its input between tiles and a quit waits for one tile at most. A change
 * restarts the refinement, except during its first pass, which always completes (it is the cheap one, and a
 * picture of a recent state beats a picture that never finishes while the mouse moves).
 *
 * <p>Used on the render thread; {@link #status()} and {@link #readBack()} from any thread.
 */
public final class RefiningRenderer implements GLEventListener {
    /** The time a tile should take: the render loop's longest look away from its input. */
    public static final double TILE_MS = 100;
    /** A refinement starts at the finest pass whose frame is estimated to take at most this long. */
    public static final double START_BUDGET_MS = 100;
    /**
     * Settings drawn for the first time are taken to cost up to this many times the pass before them per pixel,
     * until their tiles tell (the preview's R = 0 and 40 nm steps do about 1/66 of the work of the thesis'
     * R = 1 and 5 nm): a tile sized too small costs a little time, one sized too large a late answer to input.
     */
    static final double UNKNOWN_COST_RATIO = 64;

    /**
     * What the window showed: RGBA floats, rows top-down, and where the refinement stood when it was shown.
     */
    public record Shown(float[] rgba, int width, int height, RefinementStatus status) {
    }

    /** What a pass draws with: the preview's settings or the configured ones. */
    public enum Quality { PREVIEW, CONFIGURED }

    /** One pass of a refinement: a quality at 1/{@code divisor} of the window's resolution. */
    public record Pass(Quality quality, int divisor) {
    }

    /** The passes of a refinement, coarse to fine. */
    public static final List<Pass> LADDER = List.of(new Pass(Quality.PREVIEW, 8), new Pass(Quality.CONFIGURED, 8),
            new Pass(Quality.CONFIGURED, 4), new Pass(Quality.CONFIGURED, 2), new Pass(Quality.CONFIGURED, 1));

    /** Everything a picture depends on; a change of any of it restarts the refinement (terms by identity). */
    private record Picture(BrdfSettings settings, ViewerState.View view, TaylorTerms terms) {
        static Picture of(ViewerState state) {
            return new Picture(state.drawableSettings(), state.view(), state.terms());
        }
    }

    /** What a draw's cost depends on besides its size (the split's right part's settings, or null). */
    private record CostKey(BrdfSettings settings, BrdfSettings splitSettings, DisplayMode mode, boolean pigmentation) {
    }

    /** A refinement of one state: its passes, the one under way and its tiles. */
    private static final class Refinement {
        final ViewerState state;
        final Picture picture;
        /** Whether the configured settings wait for their baked table: the passes draw the preview meanwhile. */
        final boolean waitingForTable;
        final List<Pass> passes = new ArrayList<>();
        final List<BrdfSettings> settings = new ArrayList<>();
        /** Per pass, the settings of an A/B split's right part, or nulls without a split. */
        final List<BrdfSettings> splitSettings = new ArrayList<>();
        int first;
        int index;
        TiledFrame frame;
        FloatFramebuffer framebuffer;
        /** The last pass completed in this refinement, and the kind of draw it was. */
        TiledFrame.Cost lastCost;
        CostKey lastKey;
        boolean failed;

        Refinement(ViewerState state, boolean waitingForTable) {
            this.state = state;
            this.picture = Picture.of(state);
            this.waitingForTable = waitingForTable;
        }

        boolean isDone() {
            return index >= passes.size();
        }

        /** Whether a change may stop it: not during its first pass. */
        boolean mayRestart() {
            return index > first || failed;
        }
    }

    private final ViewerModel model;
    private final ViewerRenderer renderer;
    private final TableBaker baker;
    private final Map<CostKey, TiledFrame.Cost> costs = new HashMap<>();
    private final List<FloatFramebuffer> spareFramebuffers = new ArrayList<>();
    private final Queue<CompletableFuture<Shown>> readBacks = new ConcurrentLinkedQueue<>();
    private Refinement refinement;
    /** The last complete pass, shown under the tiles of the pass under way; null before the first. */
    private FloatFramebuffer shown;
    private int windowWidth;
    private int windowHeight;
    private long passesCompleted;
    private volatile RefinementStatus status = RefinementStatus.STARTING;
    private volatile Thread renderThread;
    private volatile boolean holdLastPass;

    public RefiningRenderer(ViewerModel model, ViewerRenderer renderer, TableBaker baker) {
        this.model = model;
        this.renderer = renderer;
        this.baker = baker;
    }

    /** The thread whose {@link #display} calls draw (the render loop's); other threads' calls only show. */
    public void drawOn(Thread thread) {
        renderThread = thread;
    }

    /**
     * Holds the last pass of each refinement after its first tile, as if every further tile took for ever (unless the
     * refinement starts there: its first pass always completes). The order of events this class promises (a picture
     * before the expensive frame, input applied and a quit honoured while that frame is drawn) is then the same on a
     * machine of any speed: tests ask for it; off unless asked.
     */
    void holdLastPass(boolean hold) {
        holdLastPass = hold;
    }

    private boolean held(Refinement r) {
        return holdLastPass && r.index == r.passes.size() - 1 && r.index > r.first && r.frame != null
                && r.frame.tilesDrawn() > 0;
    }

    /** Where the refinement stands, for the title and tests. */
    public RefinementStatus status() {
        return status;
    }

    /**
     * The window's pixels as shown after the next {@link #display} call of the render loop, with the status at
     * that moment: what the user sees, for screenshots.
     */
    public CompletableFuture<Shown> readBack() {
        CompletableFuture<Shown> request = new CompletableFuture<>();
        readBacks.add(request);
        return request;
    }

    /**
     * Whether a {@link #display} call has anything to do: a picture to start, a pass to continue, a table that
     * came, or a read-back to serve. Called by the render loop, which waits for input while there is none.
     */
    public boolean needsDisplay() {
        Refinement r = refinement;
        if (r == null || !readBacks.isEmpty() || needsRestart(r, model.state())) {
            return true;
        }
        return !r.failed && !r.isDone() && !held(r);
    }

    /** Whether the picture changed, or the table the refinement waited for came. */
    private boolean needsRestart(Refinement r, ViewerState state) {
        return !Picture.of(state).equals(r.picture) || r.waitingForTable && tableReady(r.state);
    }

    @Override
    public void init(GLAutoDrawable drawable) {
        renderer.init(drawable);
    }

    @Override
    public void reshape(GLAutoDrawable drawable, int x, int y, int width, int height) {
        renderer.reshape(drawable, x, y, width, height);
        if (width != windowWidth || height != windowHeight) {
            windowWidth = width;
            windowHeight = height;
            deleteFramebuffers(drawable.getGL().getGL3());
            refinement = null; // starts again at the new size
        }
    }

    /**
     * On the render loop's thread: starts or continues the refinement by a tile (a few if they are quick), then
     * shows the picture. On another thread (the window system asks for a repaint, as NEWT does when the window
     * appears or is uncovered): only shows the picture, so drawing stays with the loop.
     */
    @Override
    public void display(GLAutoDrawable drawable) {
        GL3 gl = drawable.getGL().getGL3();
        // the framebuffer the caller bound for this frame (a window's, or an offscreen target's): plain GL, where
        // JOGL's getDefaultDrawFramebuffer is unknown to a headless EGL context
        int[] bound = new int[1];
        gl.glGetIntegerv(GL.GL_DRAW_FRAMEBUFFER_BINDING, bound, 0);
        int target = bound[0];
        if (Thread.currentThread() == renderThread && windowWidth > 0 && windowHeight > 0) {
            step(gl, target);
            serveReadBacks(gl, target);
        } else {
            present(gl, target);
        }
    }

    private void step(GL3 gl, int target) {
        ViewerState state = model.state();
        if (refinement == null || refinement.mayRestart() && needsRestart(refinement, state)) {
            start(state);
        }
        Refinement r = refinement;
        long start = System.nanoTime();
        try {
            // quick tiles (the background, a fast GPU) go several to a call, so showing them costs little
            do {
                if (r.failed || r.isDone() || held(r) || r.mayRestart() && needsRestart(r, model.state())) {
                    break;
                }
                drawTile(gl, r);
            } while ((System.nanoTime() - start) / 1e6 < TILE_MS / 2);
        } catch (RuntimeException e) {
            // a program that fails to compile, a texture too large: say so, and do not retry this picture
            r.failed = true;
            System.err.println("diffract: drawing failed: " + e.getMessage());
            model.update(s -> s.withNotice(Notice.forSeconds("drawing failed: " + e.getMessage(), 10)));
            publish(r);
        }
        present(gl, target);
    }

    private void start(ViewerState state) {
        BrdfSettings configured = state.drawableSettings();
        BrdfSettings configuredB = state.drawableSplitSettings();
        // a table in the disk cache loads in a fraction of a second: drawn at once, not previewed while it "bakes";
        // before the window's first picture it loads in the background instead, behind the preview (a picture first)
        boolean loadNow = shown != null;
        boolean waitingA = configured.variant().drawsTable() && !tableReady(state, configured)
                && !(loadNow && baker.loadStored(state.terms(), configured));
        boolean waitingB = configuredB != null && configuredB.variant().drawsTable()
                && !tableReady(state, configuredB) && !(loadNow && baker.loadStored(state.terms(), configuredB));
        boolean waiting = waitingA || waitingB;
        BrdfSettings preview = PreviewPolicy.settings(configured, !waitingA);
        BrdfSettings previewB = configuredB == null ? null : PreviewPolicy.settings(configuredB, !waitingB);
        Refinement r = new Refinement(state, waiting);
        for (Pass pass : LADDER) {
            Pass drawn = waiting ? new Pass(Quality.PREVIEW, pass.divisor()) : pass;
            // the same quality at the same size once is enough (a preview that is the configured settings)
            BrdfSettings settings = drawn.quality() == Quality.PREVIEW ? preview : configured;
            BrdfSettings settingsB = drawn.quality() == Quality.PREVIEW ? previewB : configuredB;
            int last = r.passes.size() - 1;
            boolean twice = last >= 0 && r.passes.get(last).divisor() == drawn.divisor()
                    && r.settings.get(last).equals(settings)
                    && java.util.Objects.equals(r.splitSettings.get(last), settingsB);
            if (!twice) {
                r.passes.add(drawn);
                r.settings.add(settings);
                r.splitSettings.add(settingsB);
            }
        }
        for (int i = r.passes.size() - 1; i > 0; i--) {
            TiledFrame.Cost cost = costs.get(costKey(state, r.settings.get(i), r.splitSettings.get(i)));
            int divisor = r.passes.get(i).divisor();
            if (cost != null && cost.frameMs(size(windowWidth, divisor), size(windowHeight, divisor), TILE_MS)
                    <= START_BUDGET_MS) {
                r.first = i;
                r.index = i;
                break;
            }
        }
        if (waitingA) {
            baker.ensureBaked(state.terms(), configured);
        } else if (waitingB) {
            baker.ensureBaked(state.terms(), configuredB);
        }
        if (refinement != null && refinement.framebuffer != null) {
            spareFramebuffers.add(refinement.framebuffer);
        }
        refinement = r;
        publish(r);
    }

    private void drawTile(GL3 gl, Refinement r) {
        BrdfSettings settings = r.settings.get(r.index);
        BrdfSettings settingsB = r.splitSettings.get(r.index);
        CostKey key = costKey(r.state, settings, settingsB);
        if (r.frame == null) {
            int divisor = r.passes.get(r.index).divisor();
            r.frame = new TiledFrame(size(windowWidth, divisor), size(windowHeight, divisor), TILE_MS, profile(r, key));
            r.framebuffer = framebuffer(gl, r.frame.width(), r.frame.height());
        }
        TiledFrame frame = r.frame;
        r.framebuffer.bind(gl);
        if (frame.tilesDrawn() == 0) {
            // builds the material if new and draws the shadow map, then one pixel, for a software rasteriser
            // compiles a program at its first draw: none of this is the tiles' cost
            for (BrdfSettings s : settingsB == null ? List.of(settings) : List.of(settingsB, settings)) {
                renderer.prepareFrame(r.state, s, frame.width(), frame.height());
                renderer.displayTile(frame.width(), frame.height(), new PixelRect(0, frame.height() - 1, 1, 1));
            }
            gl.glFinish();
        }
        long start = System.nanoTime();
        PixelRect tile = frame.nextTile();
        if (settingsB == null) {
            renderer.displayTile(frame.width(), frame.height(), tile);
        } else {
            // A left of the divider, B right of it: the tile's two parts, each with its own material
            int divider = (int) Math.round(r.state.view().split().divider() * frame.width());
            int leftWidth = Math.max(0, Math.min(tile.width(), divider - tile.x()));
            PixelRect left = new PixelRect(tile.x(), tile.y(), leftWidth, tile.height());
            PixelRect right = new PixelRect(tile.x() + leftWidth, tile.y(), tile.width() - leftWidth, tile.height());
            if (!right.isEmpty()) {
                renderer.prepareFrame(r.state, settingsB, frame.width(), frame.height());
                renderer.displayTile(frame.width(), frame.height(), right);
            }
            renderer.prepareFrame(r.state, settings, frame.width(), frame.height());
            if (!left.isEmpty()) {
                renderer.displayTile(frame.width(), frame.height(), left);
            }
        }
        gl.glFinish(); // the tile's time includes the GPU's work, and no GL call is left running
        frame.tileDrawn(tile, (System.nanoTime() - start) / 1e6);
        if (frame.isComplete()) {
            r.lastKey = key;
            r.lastCost = frame.cost();
            costs.put(key, r.lastCost);
            if (shown != null) {
                spareFramebuffers.add(shown);
            }
            shown = r.framebuffer;
            r.frame = null;
            r.framebuffer = null;
            r.index++;
            passesCompleted++;
            if (r.isDone() && !r.waitingForTable) {
                renderer.stats().record(frame.drawnMs());
                noticeShortPixels(gl, shown, settings);
            }
        }
        publish(r);
    }

    /**
     * Says in the title when pixels of the refined picture were left short: the GL ended the shader's loops before
     * their work was done ({@link ShortPixels}; Mesa's llvmpipe after 65535 iterations), so they miss lobes and are too
     * dark. Read once a refinement, for the methods that report it.
     */
    private void noticeShortPixels(GL3 gl, FloatFramebuffer picture, BrdfSettings settings) {
        if (!GpuMethods.of(settings.variant()).reportsShortPixels()) {
            return;
        }
        long count = new ShortPixels().countIn(picture.readRgbaTopDown(gl)).count();
        if (count > 0) {
            String text = String.format(Locale.ROOT, "%d px left short (the GL ended their loops early): too dark "
                    + "there; a GPU or a coarser --lobe-quadrature draws them whole", count);
            model.update(s -> s.withNotice(Notice.forSeconds(text, 10)));
        }
    }

    /** The last complete pass scaled to the window, the tiles of the pass under way over it. */
    private void present(GL3 gl, int target) {
        gl.glBindFramebuffer(GL.GL_FRAMEBUFFER, target);
        gl.glViewport(0, 0, windowWidth, windowHeight);
        if (shown == null) {
            float[] c = ViewerRenderer.CLEAR_COLOUR;
            gl.glClearColor(c[0], c[1], c[2], c[3]);
            gl.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT);
        } else {
            shown.blitTo(gl, PixelRect.of(shown.width(), shown.height()), target,
                    PixelRect.of(windowWidth, windowHeight));
        }
        Refinement r = refinement;
        if (r != null && r.frame != null && r.frame.tilesDrawn() > 0) {
            r.frame.blitDrawnPart(gl, r.framebuffer, target, windowWidth, windowHeight);
        }
        ViewerState.Split split = r != null ? r.state.view().split() : null;
        if (split != null) {
            // the A/B divider: a column of light grey across the window
            int x = (int) Math.round(split.divider() * windowWidth);
            gl.glEnable(GL.GL_SCISSOR_TEST);
            gl.glScissor(Math.max(0, Math.min(windowWidth - 1, x)), 0, 1, windowHeight);
            gl.glClearColor(0.8f, 0.8f, 0.8f, 1f);
            gl.glClear(GL.GL_COLOR_BUFFER_BIT);
            gl.glDisable(GL.GL_SCISSOR_TEST);
        }
    }

    /** Reads the picture just shown (the back buffer, before the swap) for the waiting read-backs. */
    private void serveReadBacks(GL3 gl, int framebuffer) {
        CompletableFuture<Shown> request = readBacks.poll();
        if (request == null) {
            return;
        }
        int width = windowWidth;
        int height = windowHeight;
        gl.glBindFramebuffer(GL.GL_READ_FRAMEBUFFER, framebuffer);
        gl.glReadBuffer(framebuffer == 0 ? GL.GL_BACK : GL.GL_COLOR_ATTACHMENT0);
        float[] topDown = diffract.jrtr.textures.FloatFramebuffer.readBoundRgbaTopDown(gl, width, height);
        Shown shownNow = new Shown(topDown, width, height, status);
        for (; request != null; request = readBacks.poll()) {
            request.complete(shownNow);
        }
    }

    private void publish(Refinement r) {
        Pass pass = r.passes.get(Math.min(r.index, r.passes.size() - 1));
        RefinementStatus.Stage stage;
        if (r.failed) {
            stage = RefinementStatus.Stage.FAILED;
        } else if (r.isDone()) {
            stage = r.waitingForTable ? RefinementStatus.Stage.WAITING_FOR_TABLE : RefinementStatus.Stage.REFINED;
        } else {
            stage = pass.quality() == Quality.PREVIEW ? RefinementStatus.Stage.PREVIEW : RefinementStatus.Stage.REFINING;
        }
        double fraction = r.frame != null ? r.frame.fractionDone() : r.isDone() ? 1 : 0;
        status = new RefinementStatus(stage, pass.divisor(), fraction, r.state, passesCompleted,
                renderer.stats().frameCount());
    }

    private boolean tableReady(ViewerState state) {
        BrdfSettings a = state.drawableSettings();
        BrdfSettings b = state.drawableSplitSettings();
        boolean aReady = !a.variant().drawsTable() || tableReady(state, a);
        boolean bReady = b == null || !b.variant().drawsTable() || tableReady(state, b);
        return (a.variant().drawsTable() || b != null && b.variant().drawsTable()) && aReady && bReady;
    }

    private boolean tableReady(ViewerState state, BrdfSettings s) {
        return s.variant().drawsTable() && model.pipeline().tables().isReady(state.terms(), s);
    }

    /**
     * What the tiles of a pass are sized by: the pass before it in this refinement (the same picture at a lower
     * resolution), scaled by how the two kinds of draw compared when both were drawn before; else the last pass of
     * this kind (an earlier picture); else null (the tiles find out).
     */
    private TiledFrame.Cost profile(Refinement r, CostKey key) {
        TiledFrame.Cost own = costs.get(key);
        if (r.lastCost == null || key.equals(r.lastKey)) {
            return r.lastCost != null ? r.lastCost : own;
        }
        TiledFrame.Cost before = costs.get(r.lastKey);
        double ratio = own != null && before != null ? own.meanMsPerPixel() / Math.max(before.meanMsPerPixel(), 1e-12)
                : UNKNOWN_COST_RATIO;
        return r.lastCost.scaledBy(ratio);
    }

    private static CostKey costKey(ViewerState state, BrdfSettings settings, BrdfSettings splitSettings) {
        return new CostKey(settings, splitSettings, state.view().mode(), state.view().pigmentationOn());
    }

    private static int size(int windowPx, int divisor) {
        return Math.max(1, (windowPx + divisor - 1) / divisor);
    }

    /** A framebuffer of this size: a spare one if there is one, else a new one. */
    private FloatFramebuffer framebuffer(GL3 gl, int width, int height) {
        for (int i = 0; i < spareFramebuffers.size(); i++) {
            FloatFramebuffer f = spareFramebuffers.get(i);
            if (f.width() == width && f.height() == height) {
                return spareFramebuffers.remove(i);
            }
        }
        return new FloatFramebuffer(gl, width, height);
    }

    private void deleteFramebuffers(GL3 gl) {
        if (refinement != null && refinement.framebuffer != null) {
            spareFramebuffers.add(refinement.framebuffer);
            refinement.framebuffer = null;
            refinement.frame = null;
        }
        if (shown != null) {
            spareFramebuffers.add(shown);
            shown = null;
        }
        for (FloatFramebuffer f : spareFramebuffers) {
            f.delete(gl);
        }
        spareFramebuffers.clear();
    }

    @Override
    public void dispose(GLAutoDrawable drawable) {
        deleteFramebuffers(drawable.getGL().getGL3());
        renderer.dispose(drawable);
        for (CompletableFuture<Shown> request = readBacks.poll(); request != null; request = readBacks.poll()) {
            request.completeExceptionally(new IllegalStateException("the window closed"));
        }
    }
}
