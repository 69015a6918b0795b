package diffract.app;

import diffract.optics.HeightField;
import diffract.optics.io.SamplingCheck;
import diffract.precompute.Precomputation;
import diffract.util.Reporter;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

import java.nio.file.Path;
import java.util.concurrent.Callable;

/** {@code diffract precompute}: thesis Algorithm 1, the Taylor-term DFTs of a patch, into a folder. */
@Command(name = "precompute", mixinStandardHelpOptions = true,
        description = {"Precompute the Taylor-term DFTs DFT_n = fftshift(ifft2((i h)^n)), n = 0..N, of a height field.",
                "A rerun with the same patch and N reuses the folder without any FFT."})
final class PrecomputeCommand implements Callable<Integer> {
    @Mixin
    PatchInput input;

    @ArgGroup(exclusive = true, multiplicity = "1")
    Order order;

    static final class Order {
        @Option(names = "--terms", paramLabel = "N", description = "Highest Taylor order N (terms n = 0..N).")
        Integer highestOrder;

        @Option(names = "--tolerance", paramLabel = "EPS",
                description = "Choose the smallest N whose Lagrange remainder x^(N+1) e^x / (N+1)! <= EPS.")
        Double tolerance;
    }

    @Option(names = "--lambda-min", paramLabel = "NM", defaultValue = "380",
            description = "Shortest wavelength rendered, nm (enters the bound; default ${DEFAULT-VALUE}).")
    double lambdaMinNm;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "DIR", description = "Output folder.")
    Path output;

    @Override
    public Integer call() {
        long start = System.nanoTime();
        Reporter reporter = Reporter.STDERR;
        HeightField field = input.load(reporter);
        SamplingCheck.warnAboutAliasing(field, lambdaMinNm, 780, reporter);
        Precomputation.Request request = new Precomputation.Request(field, input.patch.getFileName().toString(),
                input.maxHeightUm, order.highestOrder, order.tolerance, lambdaMinNm);
        Precomputation.Result result = Precomputation.intoFolder(request, output, false, reporter);
        double seconds = (System.nanoTime() - start) * 1e-9;
        System.out.printf("%s %d terms of %dx%d into %s in %.2f s%n", result.reused() ? "reused" : "computed",
                result.sidecar().termCount(), field.rows(), field.cols(), output, seconds);
        return 0;
    }
}
