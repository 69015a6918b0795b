package diffract.bench;

import diffract.jrtr.contexts.HeadlessGL;
import diffract.optics.BrdfSettings;
import diffract.optics.patches.HeightField;
import diffract.optics.spectra.TaylorExpansion;
import diffract.util.DiskCache;
import diffract.util.Reporter;
import diffract.util.UserInputException;

import java.util.List;
import java.util.Locale;

/**
 * The {@code auto} variant: the concrete GPU configuration that {@link AutoChoice} picks from the patch's measured
 * {@link AutoCalibration} for an accuracy target, as {@link BrdfSettings} every command renders with.
 */
public final class AutoVariant {
    private AutoVariant() {
    }

    /**
     * The cheapest measured configuration on this patch whose mean CIEDE2000 meets {@code maxDeltaE}.
     *
     * @param base the user's settings: what the calibration does not sweep (wavelength range, coherence, refractive
     *             index, PQ replicas) comes from here
     */
    public static AutoChoice choose(HeightField meanSubtracted, double phiIDeg, BrdfSettings base, double maxDeltaE,
                                    Reporter reporter) {
        HeadlessGL.require();
        List<BenchResult> calibration = AutoCalibration.of(meanSubtracted, phiIDeg, base, DiskCache.user(), reporter);
        return AutoChoice.choose(calibration, maxDeltaE).orElseThrow(() -> {
            BenchResult best = AutoChoice.mostAccurate(calibration).orElseThrow(
                    () -> new UserInputException("auto: the calibration measured no lit pixel on this patch"));
            return new UserInputException(String.format(Locale.ROOT, "auto: no measured configuration meets mean "
                    + "CIEDE2000 <= %s on this patch; the most accurate, %s, errs by %.3f", maxDeltaE,
                    AutoChoice.describe(best), best.deltaEMean()));
        });
    }

    /**
     * The settings a choice renders with: the chosen configuration, summed by the expansion its calibration measured
     * (the pipeline's choice for its settings) unless {@code expansion} asks for another one explicitly.
     */
    public static BrdfSettings settings(AutoChoice choice, TaylorExpansion expansion) {
        BrdfSettings measured = choice.chosen().config().settings();
        TaylorExpansion path = expansion == TaylorExpansion.AUTO ? measured.taylor().expansion() : expansion;
        return measured.with(b -> b.expansion(path));
    }
}
