package diffract.app;

import diffract.app.options.CacheOption;
import diffract.app.options.GpuOption;
import diffract.app.options.QuietOption;
import diffract.bench.IridescenceStatistics;
import diffract.jrtr.OffscreenTarget;
import diffract.scene.Scene;
import diffract.scene.SceneSetup;
import diffract.util.ImageFiles;
import diffract.util.OutputPaths;
import diffract.util.Reporter;
import diffract.viewer.ViewerModel;
import diffract.viewer.ViewerRenderer;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;

/**
 * {@code diffract measure SCENE}: renders the scene's mask (where the shape is) and its structural colour alone
 * (pigmentation off), and prints {@link IridescenceStatistics}: the shape's share of the frame, the share of
 * saturated structural colour (of the frame and of the shape), its patches and hues.
 */
@Command(name = "measure", mixinStandardHelpOptions = true, abbreviateSynopsis = true)
final class MeasureCommand implements Callable<Integer> {
    @Mixin ViewerOptions options;

    @Option(names = "--save", paramLabel = "DIR") Path saveDir;

    @Mixin GpuOption gpu;

    private static final String MASK = "mask.png";
    private static final String STRUCTURAL = "structural.png";

    @Mixin QuietOption quiet;
    @Mixin CacheOption cache;

    @Override
    public Integer call() throws Exception {
        options.validate();
        if (options.dumpedScene(new Scene.ImageSize(512, 512))) {
            return 0;
        }
        if (saveDir != null) {
            OutputPaths.require(OutputPaths.folder("--save", saveDir),
                    OutputPaths.file("--save", saveDir.resolve(MASK), MASK, ".png"),
                    OutputPaths.file("--save", saveDir.resolve(STRUCTURAL), STRUCTURAL, ".png"));
        }
        Reporter reporter = quiet.reporter();
        Scene.ImageSize size = options.imageSize(new Scene.ImageSize(512, 512));
        SceneSetup setup = options.setup(size, reporter);
        ViewerModel model = ViewerModel.load(setup, reporter);
        model.bakeIfNeeded(reporter);
        model.update(s -> s.withView(s.view().withPigmentationOn(false)));
        ViewerRenderer renderer = new ViewerRenderer(model);
        int width = size.width();
        int height = size.height();
        float[] structural;
        float[] mask;
        try (OffscreenTarget target = new OffscreenTarget(renderer)) {
            structural = RenderCommand.frameRgb(target, width, height, "pixels of the frame", reporter);
            renderer.setMaskOnly(true);
            mask = target.renderRgb(width, height);
        }
        float[] maskChannel = new float[width * height];
        for (int p = 0; p < maskChannel.length; p++) {
            maskChannel[p] = mask[3 * p];
        }
        if (saveDir != null) {
            Files.createDirectories(saveDir);
            ImageFiles.writePng(saveDir.resolve(MASK), mask, width, height, 3);
            ImageFiles.writePng(saveDir.resolve(STRUCTURAL), structural, width, height, 3);
        }
        System.out.println(IridescenceStatistics.of(maskChannel, structural, width, height));
        return 0;
    }
}
