package diffract.app;

import diffract.app.options.PatchOptions;
import diffract.app.options.QuietOption;
import diffract.optics.io.SamplingCheck;
import diffract.optics.patches.HeightField;
import diffract.optics.settings.SpectralSettings;
import diffract.pipeline.NamedPatch;
import diffract.precompute.Precomputation;
import diffract.precompute.TermFolders;
import diffract.util.OutputPaths;
import diffract.util.Reporter;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

import java.nio.file.Path;
import java.util.concurrent.Callable;

/** {@code diffract precompute}: thesis Algorithm 1, the Taylor-term DFTs of a patch, into a folder. */
@Command(name = "precompute", mixinStandardHelpOptions = true)
final class PrecomputeCommand implements Callable<Integer> {
    @Mixin PatchOptions patch;
    @Mixin QuietOption quiet;

    @ArgGroup(exclusive = true, multiplicity = "1")
    Order order;

    static final class Order {
        @Option(names = "--terms", paramLabel = "N") Integer highestOrder;

        @Option(names = "--tolerance", paramLabel = "EPS") Double tolerance;
    }

    @Option(names = "--lambda-min", paramLabel = "NM", defaultValue = "380") double lambdaMinNm;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "DIR") Path output;

    @Option(names = "--format", defaultValue = "native", paramLabel = "F") TermFolders.Format format;

    @Override
    public Integer call() {
        long start = System.nanoTime();
        patch.validateRequired();
        OutputPaths.requireWritableFolder(output, "-o");
        Reporter reporter = quiet.reporter();
        NamedPatch named = patch.load("", reporter);
        HeightField field = named.meanSubtracted();
        // no light here: only what aliases for every light (a render notes what its own light adds)
        SamplingCheck.warnAboutAliasing(field, lambdaMinNm, SpectralSettings.LAMBDA_MAX_NM, 0, reporter);
        Precomputation.Request request = new Precomputation.Request(field, named.name(), named.maxHeightUm(),
                order.highestOrder, order.tolerance, lambdaMinNm);
        boolean reused;
        int termCount;
        if (format == TermFolders.Format.THESIS) {
            Precomputation.ThesisResult result = Precomputation.intoThesisFolder(request, output, reporter);
            reused = result.reused();
            termCount = result.termCount();
        } else {
            Precomputation.Result result = Precomputation.intoFolder(request, output, false, reporter);
            reused = result.reused();
            termCount = result.sidecar().termCount();
        }
        double seconds = (System.nanoTime() - start) * 1e-9;
        System.out.printf("%s %d terms of %dx%d (%s format) into %s in %.2f s%n", reused ? "reused" : "computed",
                termCount, field.rows(), field.cols(), format.name().toLowerCase(java.util.Locale.ROOT), output, seconds);
        return 0;
    }
}
