package diffract.app;

import diffract.optics.HeightField;
import diffract.optics.PatchCatalogue;
import diffract.optics.io.GsfWriter;
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
@Command(name = "patch", mixinStandardHelpOptions = true,
        description = "Write a patch made by code as a Gwyddion Simple Field (.gsf, heights and pixel size in metres). "
                + "Grating grooves run along y (rows); the period lies along x (columns). The snake patches' ridges "
                + "run along x; their period lies along y (view them with --phi-i 90).")
final class PatchCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "NAME", completionCandidates = OptionTypes.PatchNames.class,
            description = "One of ${COMPLETION-CANDIDATES}; the options below change its parameters.")
    String name;

    @Mixin
    ProceduralOptions parameters;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "FILE.gsf")
    Path output;

    @Override
    public Integer call() throws IOException {
        if (!output.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".gsf")) {
            throw new UserInputException("patch writes Gwyddion .gsf files; name the output FILE.gsf");
        }
        HeightField field = parameters.spec(PatchCatalogue.named(name)).build();
        GsfWriter.write(output, field);
        System.out.printf(Locale.ROOT, "wrote %s: %d x %d pixels of %.4f um (%.2f x %.2f um)%n", output, field.cols(),
                field.rows(), field.pixelSizeXUm(), field.widthUm(), field.heightExtentUm());
        return 0;
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
