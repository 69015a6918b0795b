package diffract.app;

import diffract.jrtr.OffscreenTarget;
import diffract.render.FrameOutput;
import diffract.scene.DisplayMode;
import diffract.scene.Scene;
import diffract.scene.SceneSetup;
import diffract.util.OpenExr;
import diffract.util.OutputPaths;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import diffract.viewer.ViewerModel;
import diffract.viewer.ViewerRenderer;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;

/**
 * {@code diffract render}: one frame of what {@code view} would show, drawn offscreen into a PNG (or, as linear
 * light, an OpenEXR file), or with {@code --turntable} many frames into a looping GIF or a PNG sequence.
 */
@Command(name = "render", mixinStandardHelpOptions = true, abbreviateSynopsis = true,
        description = "Render one frame of the viewer offscreen and write it as a PNG, or as an OpenEXR file of "
                + "linear light (with --turntable, frames going round into a looping GIF or a numbered PNG "
                + "sequence): the same model, renderer and shaders as 'diffract view', without a window or X server "
                + "(headless EGL; see docs/headless-gl.md).")
final class RenderCommand implements Callable<Integer> {
    @Mixin
    GpuOption gpu;

    @Mixin
    ViewerOptions options;

    @Mixin
    QuietOption quiet;

    @Mixin
    CacheOption cache;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "OUT.png|OUT.exr|OUT.gif",
            description = "The PNG to write (tone mapped, display sRGB), or an OpenEXR file of the frame's linear "
                    + "light (linear sRGB times the exposure, neither tone mapped nor clipped); with --turntable a "
                    + ".gif (animated, looping), or a .png name for the numbered sequence OUT-000.png, OUT-001.png, "
                    + "...")
    Path output;

    @Option(names = "--exr-half",
            description = "With -o OUT.exr: store half floats (11 significant bits, finite up to 65504) instead of "
                    + "32-bit floats.")
    boolean exrHalf;

    @ArgGroup(exclusive = false, validate = false, heading = "Turntable:%n")
    TurntableOptions turntable = new TurntableOptions();

    /** Many frames instead of one: the camera or the light goes once round the scene. */
    static final class TurntableOptions {
        @Option(names = "--turntable", paramLabel = "FRAMES",
                description = "Render FRAMES frames with the camera going once round the scene (2..720).")
        Integer frames;

        @Option(names = "--orbit-light",
                description = "With --turntable: the key light (and the environment) goes round instead of the camera.")
        boolean orbitLight;

        @Option(names = "--frame-ms", defaultValue = "80", paramLabel = "MS",
                description = "With --turntable and a .gif: milliseconds per frame, 10..10000 (default "
                        + "${DEFAULT-VALUE}).")
        int frameMs = 80;
    }

    @Override
    public Integer call() throws IOException {
        options.validate();
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
        OutputPaths.require(outputs(frames));
        boolean linear = frames == null && output.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".exr");
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
        try (OffscreenTarget target = new OffscreenTarget(renderer)) {
            if (frames != null) {
                Turntable.render(target, renderer, model, frames, turntable.orbitLight, output, image,
                        turntable.frameMs, reporter);
            } else if (linear) {
                OpenExr.write(output, target.renderRgb(image.width(), image.height()), image.width(), image.height(),
                        3, exrHalf ? OpenExr.Precision.HALF : OpenExr.Precision.FLOAT,
                        "diffract render: linear sRGB times the exposure, not tone mapped, not clipped");
            } else {
                target.writePng(output, image.width(), image.height());
            }
        }
        System.out.printf(Locale.ROOT, "wrote %s (%s%dx%d, %s, %s N=%d, lambda step %s nm) in %.1f s%n", output,
                frames == null ? "" : frames + " frames of ", image.width(), image.height(),
                setup.mode() == DisplayMode.BRDF_MAP ? "BRDF map" : setup.shape().name(),
                setup.settings().variant().label(), setup.settings().taylor().highestOrder(),
                setup.settings().spectral().lambdaStepNm(), (System.nanoTime() - start) * 1e-9);
        return 0;
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
