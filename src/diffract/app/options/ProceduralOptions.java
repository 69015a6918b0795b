package diffract.app.options;

import diffract.optics.patches.PatchCatalogue;
import diffract.optics.patches.ProceduralPatches;
import diffract.util.UserInputException;
import picocli.CommandLine.Option;

/**
 * The parameters of a named patch made by code ({@code patch NAME}, {@code --synthetic NAME}), the scene file's
 * {@code material.patch} keys of the same names: each replaces the catalogue's value when given.
 */
public final class ProceduralOptions {
    @Option(names = "--period", paramLabel = "UM") Double periodUm;

    @Option(names = "--height", paramLabel = "UM") Double heightUm;

    @Option(names = "--periods", paramLabel = "P") Integer periods;

    @Option(names = {"--samples-per-period"}, paramLabel = "K") Integer samplesPerPeriod;

    @Option(names = "--rows", paramLabel = "R") Integer rows;

    @Option(names = "--seed", paramLabel = "S") Long seed;

    @Option(names = "--size-px", paramLabel = "N") Integer sizePx;

    /** The largest snake patch made by code: an AFM scan's 2048 lines. */
    public static final int MAX_SIZE_PX = 2048;

    /** Whether any parameter was given. */
    public boolean given() {
        return periodUm != null || heightUm != null || periods != null || samplesPerPeriod != null || rows != null
                || seed != null || sizePx != null;
    }

    /** The parameters given, as a user would give them again: " --period 1 --height 0.3", or "". */
    String describe() {
        StringBuilder b = new StringBuilder();
        append(b, "--period", periodUm);
        append(b, "--height", heightUm);
        append(b, "--periods", periods);
        append(b, "--samples-per-period", samplesPerPeriod);
        append(b, "--rows", rows);
        append(b, "--seed", seed);
        append(b, "--size-px", sizePx);
        return b.toString();
    }

    private static void append(StringBuilder b, String option, Number value) {
        if (value != null) {
            b.append(' ').append(option).append(' ').append(value instanceof Double d
                    ? new java.math.BigDecimal(d.toString()).stripTrailingZeros().toPlainString() : value.toString());
        }
    }

    /** The named patch with the parameters given in place of its own. */
    public ProceduralPatches.Spec spec(PatchCatalogue.Entry entry) {
        ProceduralPatches.Spec d = entry.spec();
        boolean grating = d.kind().isGrating();
        if (!grating && (samplesPerPeriod != null || rows != null)) {
            throw new UserInputException("--samples-per-period and --rows size a grating; " + entry.name()
                    + " is " + d.sizePx() + " x " + d.sizePx() + " pixels");
        }
        if (grating && (seed != null || sizePx != null)) {
            throw new UserInputException("--seed and --size-px make the snake patches; a grating is sized by "
                    + "--periods, --samples-per-period and --rows");
        }
        if (sizePx != null && (sizePx < 16 || sizePx > MAX_SIZE_PX || sizePx % 16 != 0)) {
            throw new UserInputException("--size-px must be a multiple of 16 in 16.." + MAX_SIZE_PX + ", got " + sizePx);
        }
        ProceduralPatches.Spec spec = new ProceduralPatches.Spec(d.kind(), or(periodUm, d.periodUm()),
                or(heightUm, d.heightUm()), or(periods, d.periods()), or(samplesPerPeriod, d.samplesPerPeriod()),
                or(rows, d.rows()), or(sizePx, d.sizePx()), d.roughnessUm(), seed != null ? seed : d.seed());
        if (grating) {
            checkGrating(spec);
        }
        return spec;
    }

    /** Each grating parameter in its range, named by its option (the catalogue's own values all are). */
    private static void checkGrating(ProceduralPatches.Spec s) {
        if (!(s.periodUm() > 0) || !Double.isFinite(s.periodUm())) {
            throw new UserInputException("--period must be a positive number of micrometres, got " + s.periodUm());
        }
        if (!(s.heightUm() >= 0) || !Double.isFinite(s.heightUm())) {
            throw new UserInputException("--height must be >= 0 um, got " + s.heightUm());
        }
        if (s.samplesPerPeriod() < 2) {
            throw new UserInputException("--samples-per-period must be at least 2, got " + s.samplesPerPeriod());
        }
        if (s.periods() < 1) {
            throw new UserInputException("--periods must be at least 1, got " + s.periods());
        }
        if (s.rows() < 1) {
            throw new UserInputException("--rows must be at least 1, got " + s.rows());
        }
    }

    private static <T> T or(T given, T fallback) {
        return given != null ? given : fallback;
    }
}
