package diffract.app;

import diffract.jrtr.OffscreenTarget;
import diffract.scene.DisplayMode;
import diffract.scene.Scene;
import diffract.scene.SceneSetup;
import diffract.util.OutputPaths;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import diffract.viewer.ViewerModel;
import diffract.viewer.ViewerRenderer;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;

/** {@code diffract render}: one frame of what {@code view} would show, drawn offscreen into a PNG. */
@Command(name = "render", mixinStandardHelpOptions = true, abbreviateSynopsis = true,
        description = "Render one frame of the viewer offscreen and write it as a PNG: the same model, renderer and "
                + "shaders as 'diffract view', without a window or X server (headless EGL; see docs/headless-gl.md).")
final class RenderCommand implements Callable<Integer> {
    @Mixin
    GpuOption gpu;

    @Mixin
    ViewerOptions options;

    @Mixin
    QuietOption quiet;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "OUT.png", description = "PNG to write.")
    Path output;

    @Override
    public Integer call() throws IOException {
        options.validate();
        if (!output.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".png")) {
            throw new UserInputException("render writes PNG files; name the output OUT.png");
        }
        OutputPaths.requireWritableFile(output, "-o", "render.png");
        long start = System.nanoTime();
        Reporter reporter = quiet.reporter();
        Scene.ImageSize image = options.imageSize(new Scene.ImageSize(512, 512));
        SceneSetup setup = options.setup(image, reporter);
        ViewerModel model = ViewerModel.load(setup, reporter);
        model.bakeIfNeeded(reporter);
        try (OffscreenTarget target = new OffscreenTarget(new ViewerRenderer(model))) {
            target.writePng(output, image.width(), image.height());
        }
        System.out.printf(Locale.ROOT, "wrote %s (%dx%d, %s, %s N=%d, lambda step %s nm) in %.1f s%n", output,
                image.width(), image.height(), setup.mode() == DisplayMode.BRDF_MAP ? "BRDF map" : setup.shape().name(),
                setup.settings().variant().label(), setup.settings().taylor().highestOrder(),
                setup.settings().spectral().lambdaStepNm(), (System.nanoTime() - start) * 1e-9);
        return 0;
    }
}
