package diffract.app;

import diffract.optics.HeightField;
import diffract.optics.SyntheticPatches;
import diffract.optics.io.GsfWriter;
import diffract.util.UserInputException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;

/** {@code diffract patch}: writes a synthetic height field made by code as a Gwyddion .gsf file. */
@Command(name = "patch", mixinStandardHelpOptions = true,
        description = {"Write a synthetic grating as a Gwyddion Simple Field (.gsf, heights and pixel size in metres).",
                "Grooves run along y (rows); the period lies along x (columns)."})
final class PatchCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "KIND", description = "blazed (sawtooth) or sinusoid")
    String kind;

    @Option(names = "--period", defaultValue = "2.5", paramLabel = "UM", description = "Grating period d (default ${DEFAULT-VALUE}).")
    double periodUm;

    @Option(names = "--height", defaultValue = "0.2", paramLabel = "UM", description = "Peak-to-valley height (default ${DEFAULT-VALUE}).")
    double heightUm;

    @Option(names = "--samples-per-period", defaultValue = "25", paramLabel = "K", description = "Pixels per period (default ${DEFAULT-VALUE}).")
    int samplesPerPeriod;

    @Option(names = "--periods", defaultValue = "26", paramLabel = "P", description = "Whole periods across (default ${DEFAULT-VALUE}: 65 um at 2.5 um).")
    int periods;

    @Option(names = "--rows", defaultValue = "16", paramLabel = "R", description = "Rows (default ${DEFAULT-VALUE}).")
    int rows;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "FILE.gsf")
    Path output;

    @Override
    public Integer call() throws IOException {
        HeightField field;
        switch (kind.toLowerCase(Locale.ROOT)) {
            case "blazed":
                field = SyntheticPatches.blazed(periodUm, heightUm, samplesPerPeriod, periods, rows);
                break;
            case "sinusoid":
                field = SyntheticPatches.sinusoid(periodUm, heightUm, samplesPerPeriod, periods, rows);
                break;
            default:
                throw new UserInputException("unknown patch kind '" + kind + "': use blazed or sinusoid");
        }
        if (!output.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".gsf")) {
            throw new UserInputException("patch writes Gwyddion .gsf files; name the output FILE.gsf");
        }
        GsfWriter.write(output, field);
        System.out.printf(Locale.ROOT, "wrote %s: %d x %d pixels of %.4f um (%.2f x %.2f um)%n", output, field.cols(),
                field.rows(), field.pixelSizeXUm(), field.widthUm(), field.heightExtentUm());
        return 0;
    }
}
