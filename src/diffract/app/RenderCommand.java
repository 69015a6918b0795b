package diffract.app;

import diffract.app.jobs.PieceFolder;
import diffract.app.jobs.PieceManifest;
import diffract.app.jobs.SplitCommand;
import diffract.app.jobs.TileOptions;
import diffract.app.options.CacheOption;
import diffract.app.options.GpuOption;
import diffract.app.options.QuietOption;
import diffract.jrtr.OffscreenTarget;
import diffract.render.FrameOutput;
import diffract.render.ShortPixels;
import diffract.scene.DisplayMode;
import diffract.scene.Scene;
import diffract.scene.SceneSetup;
import diffract.util.ImageFiles;
import diffract.util.OpenExr;
import diffract.util.OutputPaths;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import diffract.viewer.ViewerModel;
import diffract.viewer.ViewerRenderer;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;

/**
 * {@code diffract render}: one frame of what {@code view} would show, drawn offscreen into a PNG (or, as linear
 * light, an OpenEXR file), or with {@code --turntable} many frames into a looping GIF or a PNG sequence.
 */
@Command(name = "render", mixinStandardHelpOptions = true, abbreviateSynopsis = true)
final class RenderCommand implements Callable<Integer>, SplitCommand {
    @Mixin GpuOption gpu;
    @Mixin ViewerOptions options;
    @Mixin QuietOption quiet;
    @Mixin CacheOption cache;
    @Mixin TileOptions tiles;
    @Spec CommandSpec spec;

    @Option(names = {"-o", "--output"}, paramLabel = "OUT.png|OUT.exr|OUT.gif") Path output;

    @Option(names = "--exr-half") boolean exrHalf;

    @ArgGroup(exclusive = false, validate = false, heading = "Turntable:%n")
    TurntableOptions turntable = new TurntableOptions();

    /** What draws a scene's pixels whole where the GL ended the lobes shader's loops early ({@link ShortPixels}). */
    static final String SHORT_PIXELS_REMEDY = "draw it on a GPU, with --variant baked, or with a coarser "
            + "--lobe-quadrature (docs/design/filtering.md)";

    /** One frame drawn by {@code target}, RGB, with a warning where its pixels of {@code what} were left short. */
    static float[] frameRgb(OffscreenTarget target, int width, int height, String what, Reporter reporter) {
        ShortPixels shortPixels = new ShortPixels();
        float[] rgb = shortPixels.rgbOf(target.renderRgba(width, height));
        shortPixels.warnIfAny(reporter, what, target.info().renderer(), SHORT_PIXELS_REMEDY);
        return rgb;
    }

    /** Many frames instead of one: the camera or the light goes once round the scene. */
    static final class TurntableOptions {
        @Option(names = "--turntable", paramLabel = "FRAMES") Integer frames;

        @Option(names = "--orbit-light") boolean orbitLight;

        @Option(names = "--frame-ms", defaultValue = "80", paramLabel = "MS") int frameMs = 80;
    }

    @Override
    public Integer call() throws IOException {
        options.validate();
        if (options.dumpedScene(new Scene.ImageSize(512, 512))) {
            return 0;
        }
        Integer frames = turntable.frames;
        if (frames == null && turntable.orbitLight) {
            throw new UserInputException("--orbit-light goes with --turntable FRAMES");
        }
        if (frames != null && !(frames >= 2 && frames <= 720)) {
            throw new UserInputException("--turntable takes 2..720 frames, got " + frames);
        }
        if (!(turntable.frameMs >= 10 && turntable.frameMs <= 10_000)) {
            throw new UserInputException("--frame-ms must be in 10..10000 milliseconds, got " + turntable.frameMs);
        }
        validateTile(frames);
        if (tiles.tile == null) {
            if (output == null) {
                throw new UserInputException("render needs -o OUT.png (or OUT.exr, or with --turntable OUT.gif), the "
                        + "picture to write; with --turntable F --tile I/N --pieces DIR it writes a piece of the frames "
                        + "instead");
            }
            OutputPaths.require(outputs(frames));
        }
        boolean linear = output != null && frames == null
                && output.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".exr");
        if (exrHalf && !linear) {
            throw new UserInputException("--exr-half goes with an OpenEXR output: -o OUT.exr");
        }
        long start = System.nanoTime();
        Reporter reporter = quiet.reporter();
        Scene.ImageSize image = options.imageSize(new Scene.ImageSize(512, 512));
        SceneSetup setup = options.setup(image, reporter);
        ViewerModel model = ViewerModel.load(setup, reporter);
        model.bakeIfNeeded(reporter);
        ViewerRenderer renderer = new ViewerRenderer(model, linear ? FrameOutput.LINEAR : FrameOutput.DISPLAY);
        ShortPixels shortPixels = new ShortPixels();
        try (OffscreenTarget target = new OffscreenTarget(renderer)) {
            if (tiles.tile != null) {
                writePiece(target, renderer, model, setup, frames, image, start, shortPixels, reporter);
            } else if (frames != null) {
                Turntable.render(target, renderer, model, frames, turntable.orbitLight, output, image,
                        turntable.frameMs, shortPixels, reporter);
            } else {
                float[] rgb = shortPixels.rgbOf(target.renderRgba(image.width(), image.height()));
                if (linear) {
                    OpenExr.write(output, rgb, image.width(), image.height(), 3,
                            exrHalf ? OpenExr.Precision.HALF : OpenExr.Precision.FLOAT,
                            "diffract render: linear sRGB times the exposure, not tone mapped, not clipped");
                } else {
                    ImageFiles.writePng(output, rgb, image.width(), image.height(), 3);
                }
                if (!options.exposureAuto()) {
                    warnIfDark(rgb, linear, image, setup, model, reporter);
                }
            }
            shortPixels.warnIfAny(reporter, frames == null ? "pixels of the frame" : "pixels of the frames",
                    target.info().renderer(), SHORT_PIXELS_REMEDY);
        }
        if (tiles.tile != null) {
            return 0;
        }
        System.out.printf(Locale.ROOT, "wrote %s (%s%dx%d, %s, %s N=%d, lambda step %s nm) in %.1f s%n", output,
                frames == null ? "" : frames + " frames of ", image.width(), image.height(),
                setup.mode() == DisplayMode.BRDF_MAP ? "BRDF map" : setup.shape().name(),
                setup.settings().variant().spec(), setup.settings().taylor().highestOrder(),
                setup.settings().spectral().lambdaStepNm(), (System.nanoTime() - start) * 1e-9);
        return 0;
    }

    /**
     * Says when the still's structural colour is black or dim, and what would show it ({@link DarkStillNotice}). A
     * picture of the structural colour alone (no pigment shown, nothing staged) is read as it is; a staged one without
     * pigment through its {@link StructuralProbe}; a picture that shows the skin's pigment is not black. An OpenEXR
     * file is not exposed: only a picture without any diffracted light is worth a word there.
     */
    private void warnIfDark(float[] rgb, boolean linear, Scene.ImageSize image, SceneSetup setup, ViewerModel model,
                            Reporter reporter) {
        boolean map = setup.mode() == DisplayMode.BRDF_MAP;
        boolean pigmentShown = !map && model.state().view().pigmentationOn() && setup.pigmentation() != null;
        if (pigmentShown) {
            return;
        }
        StructuralProbe probe;
        if (map || !setup.stage().staged()) {
            probe = StructuralProbe.of(linear ? rgb : decoded(rgb), map ? null : coveredMask(rgb), setup.exposure());
        } else {
            probe = StructuralProbe.of(setup, image.width(), image.height(), reporter);
        }
        DarkStillNotice.check(probe, setup, map ? null : options.shapeKind())
                .filter(n -> !linear || !n.exposureHides())
                .ifPresent(n -> {
                    if (n.warning()) {
                        reporter.warn(n.text());
                    } else {
                        reporter.info("note: " + n.text());
                    }
                });
    }

    /** Display-encoded sRGB back to linear. */
    private static float[] decoded(float[] display) {
        float[] out = new float[display.length];
        for (int i = 0; i < out.length; i++) {
            out[i] = (float) diffract.colour.Srgb.decode(Math.max(0, Math.min(1, display[i])));
        }
        return out;
    }

    /** The pixels that are not the background's clear colour, as a white-on-black mask. */
    private static float[] coveredMask(float[] rgb) {
        boolean[] covered = GpuSuite.covered(rgb);
        float[] mask = new float[rgb.length];
        for (int p = 0; p < covered.length; p++) {
            if (covered[p]) {
                mask[3 * p] = 1;
                mask[3 * p + 1] = 1;
                mask[3 * p + 2] = 1;
            }
        }
        return mask;
    }

    @Override
    public TileOptions tiles() {
        return tiles;
    }

    @Override
    public void validateSplit(int pieceCount) {
        Integer frames = turntable.frames;
        if (frames == null) {
            throw new UserInputException("submit splits a turntable's frames: add --turntable FRAMES to the render "
                    + "options (one frame takes seconds: render it alone)");
        }
        options.validate();
        if (!(frames >= 2 && frames <= 720)) {
            throw new UserInputException("--turntable takes 2..720 frames, got " + frames);
        }
        if (pieceCount > frames) {
            throw new UserInputException("--piece-count " + pieceCount + ": a turntable of " + frames + " frames has "
                    + "only " + frames + " frames to split");
        }
        if (output == null) {
            throw new UserInputException("render needs -o OUT.gif (or OUT.png for the numbered sequence), what merge "
                    + "writes");
        }
        OutputPaths.require(outputs(frames));
    }

    @Override
    public Result result() {
        return Result.to(output, turntable.frames, "frames", quiet.quiet);
    }

    /** --tile and --pieces go with --turntable, without -o (merge writes it), and split at most a piece per frame. */
    private void validateTile(Integer frames) {
        if (!tiles.requested("which run of frames to render")) {
            return;
        }
        if (frames == null) {
            throw new UserInputException("--tile splits a turntable's frames: add --turntable FRAMES");
        }
        if (output != null) {
            throw new UserInputException("--tile writes one piece into --pieces " + tiles.pieces + "; the turntable's "
                    + "-o is written by 'diffract merge " + tiles.pieces + " -o OUT.gif': drop it");
        }
        tiles.requireSplittable(frames, "a turntable of " + frames + " frames has only " + frames + " frames");
    }

    /** With --tile: the piece's frames, as linear floats, written with their manifest into --pieces DIR. */
    private void writePiece(OffscreenTarget target, ViewerRenderer renderer, ViewerModel model, SceneSetup setup,
                            int frames, Scene.ImageSize image, long startNanos, ShortPixels shortPixels,
                            Reporter reporter) throws IOException {
        TileOptions.Tile tile = tiles.tile;
        var band = diffract.optics.MapBand.of(tile.index(), tile.count(), frames);
        int perFrame = image.width() * image.height() * 3;
        float[] floats = new float[band.rows() * perFrame];
        long work = System.nanoTime();
        Turntable.render(target, renderer, model, frames, turntable.orbitLight, band.fromRow(), band.toRow(), image,
                shortPixels, reporter,
                (k, rgb) -> System.arraycopy(rgb, 0, floats, (k - band.fromRow()) * perFrame, perFrame));
        long done = System.nanoTime();
        Map<String, String> settings = new LinkedHashMap<>();
        settings.put("version", diffract.util.Version.VERSION);
        settings.put("brdf", setup.settings().toString());
        settings.put("image", image.width() + "x" + image.height());
        settings.put("orbitLight", Boolean.toString(turntable.orbitLight));
        Map<String, String> picture = new LinkedHashMap<>();
        picture.put("frameMs", Integer.toString(turntable.frameMs));
        PieceManifest manifest = new PieceManifest(PieceManifest.FORMAT, spec.name(), tile.index(), tile.count(),
                band.fromRow(), band.toRow(), frames, perFrame, setup.patch().contentSha256(), settings, picture,
                TileOptions.argumentsWithoutTile(spec), null, null, null);
        PieceFolder.write(tiles.pieces, manifest, floats);
        // submit reads this line: the piece's fixed cost (loading, the table) against its work (the frames)
        System.out.printf(Locale.ROOT, "wrote piece %s (frames %s of %d) into %s: setup %.2f s, work %.2f s%n", tile,
                band, frames, tiles.pieces, (work - startNanos) * 1e-9, (done - work) * 1e-9);
    }

    /**
     * Merge's half of a split turntable: every frame's floats, in order, written as this command would have written
     * them had it rendered them all (the same GIF or PNG sequence, bit for bit).
     */
    void writeMergedTurntable(float[] floats, Reporter reporter) throws IOException {
        Integer frames = turntable.frames;
        if (frames == null) {
            throw new UserInputException("merge: the pieces' options name no --turntable: compute them again");
        }
        OutputPaths.require(outputs(frames));
        Scene.ImageSize image = options.imageSize(new Scene.ImageSize(512, 512));
        int perFrame = image.width() * image.height() * 3;
        if ((long) perFrame * frames != floats.length) {
            throw new UserInputException("merge: the pieces hold " + floats.length + " floats, not " + frames
                    + " frames of " + image.width() + "x" + image.height() + ": compute them again with this diffract");
        }
        List<float[]> pictures = new ArrayList<>();
        for (int k = 0; k < frames; k++) {
            pictures.add(java.util.Arrays.copyOfRange(floats, k * perFrame, (k + 1) * perFrame));
        }
        Turntable.write(output, pictures, image, turntable.frameMs);
        reporter.info("wrote " + frames + " frames of " + image.width() + "x" + image.height());
    }

    /** What the command writes: one PNG or OpenEXR file, a GIF, or every name of a PNG sequence. */
    private OutputPaths.Output[] outputs(Integer frames) {
        if (frames == null) {
            return new OutputPaths.Output[] {OutputPaths.file("-o", output, "render.png", ".png", ".exr")};
        }
        Path name = output.getFileName();
        if (name == null || !name.toString().toLowerCase(Locale.ROOT).endsWith(".png")) {
            return new OutputPaths.Output[] {OutputPaths.file("-o", output, "turntable.gif", ".gif", ".png")};
        }
        OutputPaths.Output[] sequence = new OutputPaths.Output[frames];
        for (int k = 0; k < frames; k++) {
            sequence[k] = OutputPaths.file("-o", Turntable.sequenceName(output, k), "turntable-000.png", ".png");
        }
        return sequence;
    }
}
