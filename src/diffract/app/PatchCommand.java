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
                "Grating grooves run along y (rows); the period lies along x (columns).",
                "The elaphe-like patch's ridges run along x; its period lies along y (view it with --phi-i 90)."})
final class PatchCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "KIND",
            description = "blazed (sawtooth), sinusoid, or elaphe-like (a procedural snake-skin patch: 128 x 128 pixels "
                    + "of 0.0715 um, ridges along x with period 1.144 um along y, 0.3 um high; only --seed applies)")
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

    @Option(names = "--seed", defaultValue = "1", paramLabel = "S", description = "Noise seed of elaphe-like (default ${DEFAULT-VALUE}).")
    long seed;

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
            case "elaphe-like":
                field = SyntheticPatches.elapheLike(128, 8, SyntheticPatches.ELAPHE_RIDGE_PERIOD_UM, 0.3, seed);
                break;
            default:
                throw new UserInputException("unknown patch kind '" + kind + "': use blazed, sinusoid or elaphe-like");
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
