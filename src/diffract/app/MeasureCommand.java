package diffract.app;

import diffract.bench.IridescenceStatistics;
import diffract.jrtr.DisplayCheck;
import diffract.jrtr.OffscreenTarget;
import diffract.util.ImageFiles;
import diffract.util.Reporter;
import diffract.viewer.ViewerModel;
import diffract.viewer.ViewerRenderer;
import diffract.viewer.ViewerSetup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;

/**
 * {@code diffract measure SCENE}: renders the scene's mask (where the shape is) and its structural colour alone
 * (pigmentation off), and prints {@link IridescenceStatistics}: the shape's share of the frame, the share of
 * saturated structural colour, its patches and hues.
 */
@Command(name = "measure", mixinStandardHelpOptions = true,
        description = {"Measure a scene's picture: the shape's share of the frame, saturated structural colour's share,",
                "its separate patches and hue bins (from a mask and a structural-colour-only render)."})
final class MeasureCommand implements Callable<Integer> {
    @Mixin
    ViewerOptions options;

    @Spec
    CommandSpec spec;

    @Option(names = "--size", defaultValue = "512x512", paramLabel = "WxH", description = "Image size (default: the scene's image, else ${DEFAULT-VALUE}).")
    String size;

    @Option(names = "--save", paramLabel = "DIR", description = "Also write mask.png and structural.png into DIR.")
    Path saveDir;

    @Override
    public Integer call() throws Exception {
        options.validate();
        ViewerOptions.parseSize(size);
        DisplayCheck.requireDisplay();
        Reporter reporter = Reporter.STDERR;
        ViewerSetup setup = options.setup(reporter);
        int[] wh = options.size(size, spec.commandLine().getParseResult().hasMatchedOption("--size"));
        ViewerModel model = ViewerModel.load(setup, options.termSource(setup), reporter);
        model.bakeIfNeeded(reporter);
        model.update(s -> s.withPigmentationOn(false));
        ViewerRenderer renderer = new ViewerRenderer(model);
        float[] structural;
        float[] mask;
        try (OffscreenTarget target = new OffscreenTarget(renderer)) {
            structural = target.renderRgb(wh[0], wh[1]);
            renderer.setMaskOnly(true);
            mask = target.renderRgb(wh[0], wh[1]);
        }
        float[] maskChannel = new float[wh[0] * wh[1]];
        for (int p = 0; p < maskChannel.length; p++) {
            maskChannel[p] = mask[3 * p];
        }
        if (saveDir != null) {
            Files.createDirectories(saveDir);
            ImageFiles.writePng(saveDir.resolve("mask.png"), mask, wh[0], wh[1], 3);
            ImageFiles.writePng(saveDir.resolve("structural.png"), structural, wh[0], wh[1], 3);
        }
        System.out.println(IridescenceStatistics.of(maskChannel, structural, wh[0], wh[1]));
        return 0;
    }
}
