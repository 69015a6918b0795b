package diffract.app;

import diffract.jrtr.DisplayCheck;
import diffract.jrtr.OffscreenTarget;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import diffract.viewer.ViewerModel;
import diffract.viewer.ViewerRenderer;
import diffract.viewer.ViewerSetup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Option;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;

/** {@code diffract render}: one frame of what {@code view} would show, drawn offscreen into a PNG. */
@Command(name = "render", mixinStandardHelpOptions = true,
        description = {"Render one frame of the viewer offscreen and write it as a PNG: the same model, renderer and",
                "shaders as 'diffract view', without a window (runs under xvfb-run; the launcher starts one)."})
final class RenderCommand implements Callable<Integer> {
    @Mixin
    ViewerOptions options;

    @Spec
    CommandSpec spec;

    @Option(names = "--size", defaultValue = "512x512", paramLabel = "WxH", description = "Image size (default: the scene's image, else ${DEFAULT-VALUE}).")
    String size;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "OUT.png",
            description = "PNG to write; with --turntable a .gif (animated, looping) or a .png name for a numbered sequence.")
    Path output;

    @Option(names = "--turntable", paramLabel = "FRAMES",
            description = "Render FRAMES frames with the camera going once round the scene (2..720).")
    Integer turntableFrames;

    @Option(names = "--orbit-light", description = "With --turntable: the key light (and the environment) goes round instead of the camera.")
    boolean orbitLight;

    @Option(names = "--frame-ms", defaultValue = "80", paramLabel = "MS", description = "With --turntable and a .gif: milliseconds per frame (default ${DEFAULT-VALUE}).")
    int frameMs;

    @Override
    public Integer call() throws IOException {
        options.validate();
        ViewerOptions.parseSize(size); // bad usage fails before any work
        String name = output.getFileName().toString().toLowerCase(Locale.ROOT);
        if (turntableFrames == null && orbitLight) {
            throw new UserInputException("--orbit-light goes with --turntable FRAMES");
        }
        if (turntableFrames != null && !(turntableFrames >= 2 && turntableFrames <= 720)) {
            throw new UserInputException("--turntable takes 2..720 frames, got " + turntableFrames);
        }
        if (!name.endsWith(".png") && !(turntableFrames != null && name.endsWith(".gif"))) {
            throw new UserInputException(turntableFrames == null ? "render writes PNG files; name the output OUT.png"
                    : "a turntable is written as OUT.gif or as a PNG sequence OUT-000.png, ...: name the output so");
        }
        DisplayCheck.requireDisplay();
        long start = System.nanoTime();
        Reporter reporter = Reporter.STDERR;
        ViewerSetup setup = options.setup(reporter);
        int[] widthHeight = options.size(size, spec.commandLine().getParseResult().hasMatchedOption("--size"));
        ViewerModel model = ViewerModel.load(setup, options.termSource(setup), reporter);
        model.bakeIfNeeded(reporter);
        ViewerRenderer renderer = new ViewerRenderer(model);
        try (OffscreenTarget target = new OffscreenTarget(renderer)) {
            if (turntableFrames != null) {
                Turntable.render(target, renderer, model, turntableFrames, orbitLight, output, widthHeight, frameMs);
            } else {
                target.writePng(output, widthHeight[0], widthHeight[1]);
            }
        }
        System.out.printf(Locale.ROOT, "wrote %s (%s%dx%d, %s, %s N=%d, lambda step %s nm) in %.1f s%n", output,
                turntableFrames == null ? "" : turntableFrames + " frames of ", widthHeight[0], widthHeight[1], setup.mode() == diffract.viewer.DisplayMode.BRDF_MAP ? "BRDF map"
                        : setup.shape().name(), setup.settings().variant().cliName(), setup.settings().highestOrder(),
                setup.settings().lambdaStepNm(), (System.nanoTime() - start) * 1e-9);
        return 0;
    }
}
