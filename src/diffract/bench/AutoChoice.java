package diffract.bench;

import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * The {@code auto} variant's rule: of the measured configurations, the cheapest (median ms/frame) whose measured
 * mean CIEDE2000 is at most the target; of equally cheap ones, the more accurate. With a fixed calibration this
 * is monotone: a stricter target never picks a configuration with a larger measured error (the laxer target's
 * choice either meets the stricter target too, and then both are the same, or its error exceeds the stricter
 * target, which the stricter choice does not).
 *
 * @param chosen            the configuration picked
 * @param cheaperRejected   the next-cheaper configuration, which missed the target (empty when none is cheaper)
 */
public record AutoChoice(BenchResult chosen, Optional<BenchResult> cheaperRejected, double maxDeltaE) {

    /** The ordering: time, then error, then the key, so the choice never depends on the calibration's order. */
    static final Comparator<BenchResult> CHEAPEST_FIRST = Comparator.comparingDouble(BenchResult::msPerFrame)
            .thenComparingDouble(BenchResult::deltaEMean)
            .thenComparing(r -> r.config().key());

    /** Empty when no measured configuration meets the target. */
    public static Optional<AutoChoice> choose(List<BenchResult> calibration, double maxDeltaE) {
        List<BenchResult> sorted = calibration.stream().filter(r -> !Double.isNaN(r.deltaEMean()))
                .sorted(CHEAPEST_FIRST).toList();
        for (int i = 0; i < sorted.size(); i++) {
            if (sorted.get(i).deltaEMean() <= maxDeltaE) {
                Optional<BenchResult> rejected = i > 0 ? Optional.of(sorted.get(i - 1)) : Optional.empty();
                return Optional.of(new AutoChoice(sorted.get(i), rejected, maxDeltaE));
            }
        }
        return Optional.empty();
    }

    /** The most accurate configuration measured, to name when no configuration meets the target. */
    public static Optional<BenchResult> mostAccurate(List<BenchResult> calibration) {
        return calibration.stream().filter(r -> !Double.isNaN(r.deltaEMean()))
                .min(Comparator.comparingDouble(BenchResult::deltaEMean).thenComparing(CHEAPEST_FIRST));
    }

    /** Two lines: the choice with its measured error and time, and why nothing cheaper was taken. */
    public String explanation() {
        String why = cheaperRejected.map(r -> String.format(Locale.ROOT,
                "the next cheaper, %s, takes %.2f ms/frame but errs by %.3f > %s", describe(r), r.msPerFrame(),
                r.deltaEMean(), Csv.number(maxDeltaE))).orElse("no measured configuration is cheaper");
        return String.format(Locale.ROOT, "auto: %s, measured %.2f ms/frame and mean CIEDE2000 %.3f <= %s%n"
                + "auto: chosen because it is the cheapest that meets the target; %s", describe(chosen),
                chosen.msPerFrame(), chosen.deltaEMean(), Csv.number(maxDeltaE), why);
    }

    /** "flss, N = 16, 10 nm, R = 0, rg8", or with the early stop "flss, N = 30, 5 nm, R = auto, stop at 0.0001, rg32f". */
    public static String describe(BenchResult r) {
        BenchConfig c = r.config();
        if (c.settings().variant() == diffract.optics.Variant.LOBES) {
            // exact in wavelength, whole texels, its own float32 weight table: only N applies
            return String.format(Locale.ROOT, "lobes, N = %d", c.settings().taylor().highestOrder());
        }
        double tolerance = c.settings().taylor().tolerance();
        return String.format(Locale.ROOT, "%s, N = %d, %s nm, R = %s, %s%s", c.settings().variant().label(),
                c.settings().taylor().highestOrder(), Csv.number(c.settings().spectral().lambdaStepNm()),
                c.windowRadiusLabel(),
                tolerance > 0 ? "stop at " + Csv.number(tolerance) + ", " : "", c.textureFormat());
    }
}
