package diffract.app;

import diffract.jrtr.OffscreenTarget;
import diffract.util.OutputPaths;
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
                "shaders as 'diffract view', without a window or X server (headless EGL; see docs/headless-gl.md)."})
final class RenderCommand implements Callable<Integer> {
    @Mixin
    GpuOption gpu;

    @Mixin
    ViewerOptions options;

    @Mixin
    QuietOption quiet;

    @Spec
    CommandSpec spec;

    @Option(names = "--size", defaultValue = "512x512", paramLabel = "WxH", description = "Image size (default: the scene's image, else ${DEFAULT-VALUE}).")
    String size;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "OUT.png", description = "PNG to write.")
    Path output;

    @Override
    public Integer call() throws IOException {
        options.validate();
        ViewerOptions.parseSize(size); // bad usage fails before any work
        if (!output.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".png")) {
            throw new UserInputException("render writes PNG files; name the output OUT.png");
        }
        OutputPaths.requireWritableFile(output, "-o", "render.png");
        long start = System.nanoTime();
        Reporter reporter = quiet.reporter();
        ViewerSetup setup = options.setup(reporter);
        int[] widthHeight = options.size(size, spec.commandLine().getParseResult().hasMatchedOption("--size"));
        ViewerModel model = ViewerModel.load(setup, options.termSource(setup), reporter);
        model.bakeIfNeeded(reporter);
        try (OffscreenTarget target = new OffscreenTarget(new ViewerRenderer(model))) {
            target.writePng(output, widthHeight[0], widthHeight[1]);
        }
        System.out.printf(Locale.ROOT, "wrote %s (%dx%d, %s, %s N=%d, lambda step %s nm) in %.1f s%n", output,
                widthHeight[0], widthHeight[1], setup.mode() == diffract.viewer.DisplayMode.BRDF_MAP ? "BRDF map"
                        : setup.shape().name(), setup.settings().variant().cliName(), setup.settings().highestOrder(),
                setup.settings().lambdaStepNm(), (System.nanoTime() - start) * 1e-9);
        return 0;
    }
}
