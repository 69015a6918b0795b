package diffract.app;

import diffract.optics.PatchCatalogue;
import diffract.optics.ProceduralPatches;
import diffract.util.UserInputException;
import picocli.CommandLine.Option;

/**
 * The parameters of a named patch made by code ({@code patch NAME}, {@code --synthetic NAME}), the scene file's
 * {@code material.patch} keys of the same names: each replaces the catalogue's value when given.
 */
final class ProceduralOptions {
    @Option(names = "--period", paramLabel = "UM", description = "Grating or ridge period d (scene: periodUm).")
    Double periodUm;

    @Option(names = "--height", paramLabel = "UM", description = "Peak-to-valley height (scene: heightUm).")
    Double heightUm;

    @Option(names = "--periods", paramLabel = "P", description = "Whole periods across (scene: periods).")
    Integer periods;

    @Option(names = {"--samples-per-period"}, paramLabel = "K",
            description = "Gratings: pixels per period (scene: samplesPerPeriod).")
    Integer samplesPerPeriod;

    @Option(names = "--rows", paramLabel = "R", description = "Gratings: rows (scene: rows).")
    Integer rows;

    @Option(names = "--seed", paramLabel = "S", description = "Snake patches: the noise seed (scene: seed).")
    Long seed;

    /** Whether any parameter was given. */
    boolean given() {
        return periodUm != null || heightUm != null || periods != null || samplesPerPeriod != null || rows != null
                || seed != null;
    }

    /** The named patch with the parameters given in place of its own. */
    ProceduralPatches.Spec spec(PatchCatalogue.Entry entry) {
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
}
