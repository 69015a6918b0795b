package diffract.app;

import diffract.optics.HeightField;
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

/** {@code diffract patch}: writes a synthetic height field made by code as a Gwyddion .gsf file. */
@Command(name = "patch", mixinStandardHelpOptions = true,
        description = {"Write a synthetic grating as a Gwyddion Simple Field (.gsf, heights and pixel size in metres).",
                "Grating grooves run along y (rows); the period lies along x (columns).",
                "The snake patches' ridges run along x; their period lies along y (view them with --phi-i 90)."})
final class PatchCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "KIND",
            description = "blazed (sawtooth), sinusoid, elaphe-like (a procedural snake-skin patch: 128 x 128 pixels "
                    + "of 0.0715 um, ridges along x with period 1.144 um along y, 0.3 um high) or xenopeltis-like "
                    + "(128 x 128 pixels of 0.08125 um, smooth ridges along x, period 0.65 um, 0.1 um high); "
                    + "for the snake patches only --seed applies")
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

    @Option(names = "--seed", defaultValue = "1", paramLabel = "S", description = "Noise seed of the snake patches (default ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "FILE.gsf")
    Path output;

    @Mixin
    QuietOption quiet;

    /** A .gsf's float32 heights go through one byte buffer: at most this many samples (2 GB). */
    static final long MAX_SAMPLES = (Integer.MAX_VALUE - 1024) / 4;

    @Override
    public Integer call() throws IOException {
        if (!output.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".gsf")) {
            throw new UserInputException("patch writes Gwyddion .gsf files; name the output FILE.gsf");
        }
        OutputPaths.requireWritableFile(output, "-o", "patch.gsf");
        ProceduralPatches.Spec spec = spec();
        if (spec.kind().equals("blazed") || spec.kind().equals("sinusoid")) {
            checkGrating();
        }
        HeightField field = spec.build();
        GsfWriter.write(output, field);
        System.out.printf(Locale.ROOT, "wrote %s: %d x %d pixels of %.4f um (%.2f x %.2f um)%n", output, field.cols(),
                field.rows(), field.pixelSizeXUm(), field.widthUm(), field.heightExtentUm());
        return 0;
    }

    /** Each grating option in its range, named; the size within what the heap and one .gsf hold. */
    private void checkGrating() {
        if (!(periodUm > 0) || !Double.isFinite(periodUm)) {
            throw new UserInputException("--period must be a positive number of micrometres, got " + periodUm);
        }
        if (!(heightUm >= 0) || !Double.isFinite(heightUm)) {
            throw new UserInputException("--height must be >= 0 um, got " + heightUm);
        }
        if (samplesPerPeriod < 2) {
            throw new UserInputException("--samples-per-period must be at least 2, got " + samplesPerPeriod);
        }
        if (periods < 1) {
            throw new UserInputException("--periods must be at least 1, got " + periods);
        }
        if (rows < 1) {
            throw new UserInputException("--rows must be at least 1, got " + rows);
        }
        long cols = (long) samplesPerPeriod * periods;
        long samples = cols * rows; // < 2^62: no overflow
        // the heights, the field's own copy and the file's float32 buffer
        MemoryEstimate.of("heights, their copy and the file's buffer", 20 * samples).require(String.format(
                Locale.ROOT, "a %d x %d grating", cols, rows), "use fewer --periods, --rows or --samples-per-period");
        if (samples > MAX_SAMPLES) {
            throw new UserInputException(String.format(Locale.ROOT, "a %d x %d grating has %.3g samples, more than one"
                    + " .gsf file holds here (%d); use fewer --periods, --rows or --samples-per-period", cols, rows,
                    (double) samples, MAX_SAMPLES));
        }
    }

    /** The CLI's kind as a procedural patch: gratings take the options, the snake patches their defaults and seed. */
    private ProceduralPatches.Spec spec() {
        switch (kind.toLowerCase(Locale.ROOT)) {
            case "blazed":
            case "sinusoid":
                return new ProceduralPatches.Spec(kind.toLowerCase(Locale.ROOT), periodUm, heightUm, periods,
                        samplesPerPeriod, rows, 0, 0, seed);
            case "elaphe-like":
            case "xenopeltis-like":
                ProceduralPatches.Spec d = ProceduralPatches.Spec.defaults(
                        kind.toLowerCase(Locale.ROOT).equals("elaphe-like") ? "elapheLike" : "xenopeltisLike");
                return new ProceduralPatches.Spec(d.kind(), d.periodUm(), d.heightUm(), d.periods(),
                        d.samplesPerPeriod(), d.rows(), d.sizePx(), d.roughnessUm(), seed);
            default:
                throw new UserInputException("unknown patch kind '" + kind
                        + "': use blazed, sinusoid, elaphe-like or xenopeltis-like");
        }
    }
}
