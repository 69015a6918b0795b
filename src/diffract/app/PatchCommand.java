package diffract.app;

import diffract.optics.HeightField;
import diffract.optics.PatchCatalogue;
import diffract.optics.ProceduralPatches;
import diffract.optics.io.GsfWriter;
import diffract.util.UserInputException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;

/** {@code diffract patch}: writes a named patch made by code as a Gwyddion .gsf file. */
@Command(name = "patch", mixinStandardHelpOptions = true,
        description = {"Write a patch made by code as a Gwyddion Simple Field (.gsf, heights and pixel size in metres).",
                "Grating grooves run along y (rows); the period lies along x (columns).",
                "The snake patches' ridges run along x; their period lies along y (view them with --phi-i 90)."})
final class PatchCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "NAME", completionCandidates = OptionTypes.PatchNames.class,
            description = "One of ${COMPLETION-CANDIDATES}; the options below change its parameters.")
    String name;

    @Option(names = "--period", paramLabel = "UM", description = "Grating or ridge period d.")
    Double periodUm;

    @Option(names = "--height", paramLabel = "UM", description = "Peak-to-valley height.")
    Double heightUm;

    @Option(names = "--periods", paramLabel = "P", description = "Whole periods across.")
    Integer periods;

    @Option(names = "--samples-per-period", paramLabel = "K", description = "Gratings: pixels per period.")
    Integer samplesPerPeriod;

    @Option(names = "--rows", paramLabel = "R", description = "Gratings: rows.")
    Integer rows;

    @Option(names = "--seed", paramLabel = "S", description = "Snake patches: the noise seed.")
    Long seed;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "FILE.gsf")
    Path output;

    @Override
    public Integer call() throws IOException {
        if (!output.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".gsf")) {
            throw new UserInputException("patch writes Gwyddion .gsf files; name the output FILE.gsf");
        }
        HeightField field = spec(PatchCatalogue.named(name)).build();
        GsfWriter.write(output, field);
        System.out.printf(Locale.ROOT, "wrote %s: %d x %d pixels of %.4f um (%.2f x %.2f um)%n", output, field.cols(),
                field.rows(), field.pixelSizeXUm(), field.widthUm(), field.heightExtentUm());
        return 0;
    }

    /** The named patch with the options given in place of its parameters. */
    private ProceduralPatches.Spec spec(PatchCatalogue.Entry entry) {
        ProceduralPatches.Spec d = entry.spec();
        boolean grating = d.kind().isGrating();
        if (!grating && (samplesPerPeriod != null || rows != null)) {
            throw new UserInputException("--samples-per-period and --rows size a grating; " + entry.name()
                    + " is " + d.sizePx() + " x " + d.sizePx() + " pixels");
        }
        if (grating && seed != null) {
            throw new UserInputException("--seed is the noise of the snake patches; a grating has none");
        }
        return new ProceduralPatches.Spec(d.kind(), or(periodUm, d.periodUm()), or(heightUm, d.heightUm()),
                or(periods, d.periods()), or(samplesPerPeriod, d.samplesPerPeriod()), or(rows, d.rows()), d.sizePx(),
                d.roughnessUm(), seed != null ? seed : d.seed());
    }

    private static <T> T or(T given, T fallback) {
        return given != null ? given : fallback;
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
