package diffract.app;

import diffract.bench.AutoCalibration;
import diffract.bench.AutoChoice;
import diffract.bench.BenchResult;
import diffract.jrtr.HeadlessGL;
import diffract.optics.BrdfSettings;
import diffract.optics.HeightField;
import diffract.util.Reporter;
import diffract.util.UserInputException;

import java.util.List;
import java.util.Locale;
import java.util.function.Predicate;

/**
 * {@code --variant auto --max-delta-e DE}: resolves to the concrete GPU configuration ({@link BrdfSettings} and
 * term format) that {@link AutoChoice} picks from the patch's measured {@link AutoCalibration}, and prints the
 * choice and why.
 */
final class AutoVariant {
    static final String NAME = "auto";

    private AutoVariant() {
    }

    static void checkOptions(boolean auto, Double maxDeltaE, Double lambdaNm) {
        if (auto && maxDeltaE == null) {
            throw new UserInputException("--variant auto needs an accuracy target: --max-delta-e DE (mean CIEDE2000, e.g. 2)");
        }
        if (!auto && maxDeltaE != null) {
            throw new UserInputException("--max-delta-e is the target of --variant auto; add --variant auto");
        }
        if (auto && !(maxDeltaE > 0)) {
            throw new UserInputException("--max-delta-e must be > 0, got " + maxDeltaE);
        }
        if (auto && lambdaNm != null) {
            throw new UserInputException("--variant auto is calibrated on colour maps; leave out --lambda");
        }
    }

    /**
     * @param base the user's settings: what the calibration does not sweep (wavelength range, coherence, refractive
     *             index, PQ replicas) comes from here
     */
    static AutoChoice choose(HeightField meanSubtracted, double phiIDeg, BrdfSettings base, double maxDeltaE,
                             Reporter reporter) {
        return choose(meanSubtracted, phiIDeg, base, maxDeltaE, reporter, r -> true);
    }

    /** As above, among the calibrated configurations the caller can render ({@code usable}). */
    static AutoChoice choose(HeightField meanSubtracted, double phiIDeg, BrdfSettings base, double maxDeltaE,
                             Reporter reporter, Predicate<BenchResult> usable) {
        HeadlessGL.require();
        List<BenchResult> calibration = AutoCalibration.of(meanSubtracted, phiIDeg, base,
                AutoCalibration.defaultCacheRoot(), reporter).stream().filter(usable).toList();
        AutoChoice choice = AutoChoice.choose(calibration, maxDeltaE).orElseThrow(() -> {
            BenchResult best = AutoChoice.mostAccurate(calibration).orElseThrow(
                    () -> new UserInputException("auto: the calibration measured no lit pixel on this patch"));
            return new UserInputException(String.format(Locale.ROOT, "auto: no measured configuration meets mean "
                    + "CIEDE2000 <= %s on this patch; the most accurate, %s, errs by %.3f", maxDeltaE,
                    AutoChoice.describe(best), best.deltaEMean()));
        });
        System.out.println(choice.explanation());
        return choice;
    }
}
