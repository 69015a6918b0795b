package diffract.app;

import diffract.app.options.OptionTypes;
import diffract.app.options.ProceduralOptions;
import diffract.app.options.QuietOption;
import diffract.optics.io.GsfWriter;
import diffract.optics.io.HeightFieldReader;
import diffract.optics.io.ScanFormat;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.Levelling;
import diffract.optics.patches.PatchCatalogue;
import diffract.optics.patches.ProceduralPatches;
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

/**
 * {@code diffract patch}: writes a named patch made by code, or with {@code --from FILE} the height field every
 * command reads from a file (its channel, units, pixel size and levelling), as a Gwyddion .gsf file.
 */
@Command(name = "patch", mixinStandardHelpOptions = true)
final class PatchCommand implements Callable<Integer> {
    @Parameters(index = "0", arity = "0..1", paramLabel = "NAME", completionCandidates = OptionTypes.PatchNames.class,
            descriptionKey = "patch-name")
    String name;

    @Option(names = "--from", paramLabel = "FILE") Path from;

    @Option(names = "--channel", paramLabel = "NAME|INDEX") String channel;

    @Option(names = "--level", paramLabel = "L", completionCandidates = OptionTypes.LevellingNames.class,
            converter = OptionTypes.LevellingNames.Converter.class)
    Levelling level;

    @Option(names = "--max-height", paramLabel = "UM") Double maxHeightUm;

    @Option(names = "--pixel-size", paramLabel = "UM") Double pixelSizeUm;

    @Mixin ProceduralOptions parameters;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "FILE.gsf") Path output;

    @Mixin QuietOption quiet;

    /** A .gsf's float32 heights go through one byte buffer: at most this many samples (2 GB). */
    static final long MAX_SAMPLES = (Integer.MAX_VALUE - 1024) / 4;

    @Override
    public Integer call() throws IOException {
        if ((name == null) == (from == null)) {
            throw new UserInputException(name == null ? "give a patch NAME to make, or --from FILE to write the height"
                    + " field read from a file" : "give a patch NAME or --from FILE, not both");
        }
        if (from == null && (channel != null || level != null || maxHeightUm != null || pixelSizeUm != null)) {
            throw new UserInputException("--channel, --level, --max-height and --pixel-size read a file: add --from"
                    + " FILE");
        }
        if (from != null && parameters.given()) {
            throw new UserInputException("--period, --height, --periods, --samples-per-period, --rows, --seed and"
                    + " --size-px change a patch made by code, not one read --from a file");
        }
        OutputPaths.requireWritableFile(output, "-o", "patch.gsf", ".gsf");
        if (from != null) {
            return writeFromFile();
        }
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

    /**
     * The height field exactly as the other commands read it (the chosen channel in micrometres, its pixel size,
     * levelled as asked, mean subtracted) into a .gsf that Gwyddion opens, so that what goes into a BRDF can be
     * checked; heights are stored as float32 metres, a relative rounding of at most 2^-24.
     */
    private int writeFromFile() throws IOException {
        ScanFormat format = HeightFieldReader.formatOf(from);
        HeightField field = HeightFieldReader.load(from, maxHeightUm, pixelSizeUm, channel, level, quiet.reporter());
        MemoryEstimate.of("the file's buffer", 4L * field.sampleCount()).require("writing " + output,
                "crop the scan");
        GsfWriter.write(output, field);
        System.out.printf(Locale.ROOT, "wrote %s: %s read as %s, %d x %d pixels of %.6g x %.6g um (%.4g x %.4g um),"
                        + " peak to valley %.6g um%n", output, from, format.words(), field.cols(), field.rows(),
                field.pixelSizeXUm(), field.pixelSizeYUm(), field.widthUm(), field.heightExtentUm(),
                field.maxHeightUm() - field.minHeightUm());
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
