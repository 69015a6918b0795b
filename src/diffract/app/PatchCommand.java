package diffract.app;

import diffract.optics.HeightField;
import diffract.optics.PatchCatalogue;
import diffract.optics.ProceduralPatches;
import diffract.optics.io.GsfWriter;
import diffract.util.MemoryEstimate;
import diffract.util.OutputPaths;
import diffract.util.UserInputException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;

/** {@code diffract patch}: writes a named patch made by code as a Gwyddion .gsf file. */
@Command(name = "patch", mixinStandardHelpOptions = true)
final class PatchCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "NAME", completionCandidates = OptionTypes.PatchNames.class,
            descriptionKey = "patch-name")
    String name;

    @Mixin ProceduralOptions parameters;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "FILE.gsf") Path output;

    @Mixin QuietOption quiet;

    /** A .gsf's float32 heights go through one byte buffer: at most this many samples (2 GB). */
    static final long MAX_SAMPLES = (Integer.MAX_VALUE - 1024) / 4;

    @Override
    public Integer call() throws IOException {
        OutputPaths.requireWritableFile(output, "-o", "patch.gsf", ".gsf");
        ProceduralPatches.Spec spec = parameters.spec(PatchCatalogue.named(name));
        if (spec.kind().isGrating()) {
            checkGratingSize(spec);
        }
        HeightField field = spec.build();
        GsfWriter.write(output, field);
        System.out.printf(Locale.ROOT, "wrote %s: %d x %d pixels of %.4f um (%.2f x %.2f um)%n", output, field.cols(),
                field.rows(), field.pixelSizeXUm(), field.widthUm(), field.heightExtentUm());
        return 0;
    }

    /** A grating's size within what the heap and one .gsf hold (its parameters are checked by the options). */
    private static void checkGratingSize(ProceduralPatches.Spec spec) {
        long cols = (long) spec.samplesPerPeriod() * spec.periods();
        long samples = cols * spec.rows(); // < 2^62: no overflow
        // the heights, the field's own copy and the file's float32 buffer
        MemoryEstimate.of("heights, their copy and the file's buffer", 20 * samples).require(
                String.format(Locale.ROOT, "a %d x %d grating", cols, spec.rows()),
                "use fewer --periods, --rows or --samples-per-period");
        if (samples > MAX_SAMPLES) {
            throw new UserInputException(String.format(Locale.ROOT, "a %d x %d grating has %.3g samples, more than one"
                    + " .gsf file holds here (%d); use fewer --periods, --rows or --samples-per-period", cols,
                    spec.rows(), (double) samples, MAX_SAMPLES));
        }
    }

    /** The catalogue with each patch's description, for the help's footer. */
    static String catalogueText() {
        StringBuilder b = new StringBuilder("Patches:%n");
        for (PatchCatalogue.Entry e : PatchCatalogue.ALL) {
            b.append(String.format(Locale.ROOT, "  %s%%n      %s%%n", e.name(), e.description()));
        }
        return b.toString();
    }
}
