package diffract.bench;

import diffract.optics.BrdfSettings;
import diffract.optics.Methods;
import diffract.optics.Variant;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.function.BiFunction;
import java.util.function.Function;

/**
 * The bench's targets, per patch, from one run: (1) at mean CIEDE2000 <= {@link #MAX_DELTA_E} the {@code auto}
 * choice is at least {@link #MIN_SPEED_UP} times faster than FLSS in the thesis' configuration (5 nm, N = 30,
 * 3 x 3 window, float32 terms); (2) NMM with the Jacobian (thesis' configuration) is within mean CIEDE2000
 * {@link #MAX_DELTA_E} of FLSS at 1 nm, measured directly between their maps (same lights, the reference's
 * exposures, lit pixels); (3) the fastest configuration within {@link #CLOSE_DELTA_E}, the bar the filtered methods
 * are held to (FilteringTargets), and its speed-up on the same FLSS.
 */
public final class Targets {
    /** The thesis' method: its configuration is the baseline, and at 1 nm the yardstick of NMM's claim. */
    private static final Variant THESIS = Methods.Role.THESIS.method();

    public static final double MAX_DELTA_E = 2.0;
    public static final double MIN_SPEED_UP = 10.0;
    /** The closer error bar: a difference of colour most people do not see. */
    public static final double CLOSE_DELTA_E = 1.0;

    /**
     * One patch's outcome.
     *
     * @param autoChoice      empty when no configuration meets the error target
     * @param closeChoice     the fastest within {@link #CLOSE_DELTA_E}; empty when none is
     * @param nmmVersusFlss1nm null when the run lacks NMM or FLSS at 1 nm
     */
    public record Outcome(String patch, BenchResult flssThesis, Optional<AutoChoice> autoChoice,
                          Optional<AutoChoice> closeChoice, MapError nmmVersusFlss1nm, BenchResult nmm,
                          BenchResult flss1nm) {
        public double speedUp() {
            return speedUp(autoChoice);
        }

        /** The speed-up on FLSS (thesis) of the configuration within {@link #CLOSE_DELTA_E}; NaN where none is. */
        public double closeSpeedUp() {
            return speedUp(closeChoice);
        }

        private double speedUp(Optional<AutoChoice> choice) {
            return choice.map(c -> flssThesis.msPerFrame() / c.chosen().msPerFrame()).orElse(Double.NaN);
        }

        public boolean speedTargetMet() {
            return speedUp() >= MIN_SPEED_UP;
        }

        public boolean nmmTargetMet() {
            return nmmVersusFlss1nm != null && nmmVersusFlss1nm.mean() <= MAX_DELTA_E;
        }
    }

    private Targets() {
    }

    /**
     * @param maps the kept GPU maps of a configuration ({@link BenchRunner#maps}), null when not kept
     * @param exposures the reference's exposure per light of a patch at a size
     */
    public static List<Outcome> of(List<BenchResult> results, int sizePx, Function<BenchConfig, List<float[]>> maps,
                                   BiFunction<String, Integer, List<Double>> exposures) {
        List<Outcome> outcomes = new ArrayList<>();
        for (String patch : results.stream().map(r -> r.config().patch()).distinct().toList()) {
            List<BenchResult> ofPatch = results.stream()
                    .filter(r -> r.config().patch().equals(patch) && r.config().sizePx() == sizePx).toList();
            Optional<BenchResult> flssThesis = find(ofPatch, THESIS, 5);
            if (flssThesis.isEmpty()) {
                continue;
            }
            Optional<BenchResult> nmm = find(ofPatch, Variant.NMM, 5);
            Optional<BenchResult> flss1nm = find(ofPatch, THESIS, 1);
            MapError direct = null;
            if (nmm.isPresent() && flss1nm.isPresent() && maps.apply(nmm.get().config()) != null
                    && maps.apply(flss1nm.get().config()) != null) {
                direct = MapError.pooled(maps.apply(flss1nm.get().config()), maps.apply(nmm.get().config()),
                        exposures.apply(patch, sizePx), sizePx);
            }
            outcomes.add(new Outcome(patch, flssThesis.get(), AutoChoice.choose(ofPatch, MAX_DELTA_E),
                    AutoChoice.choose(ofPatch, CLOSE_DELTA_E), direct, nmm.orElse(null), flss1nm.orElse(null)));
        }
        return outcomes;
    }

    /** Whether a configuration's maps are needed for the NMM target: NMM and FLSS at 1 nm, thesis otherwise. */
    public static boolean needsMaps(BenchConfig c) {
        Variant v = c.settings().variant();
        double step = c.settings().spectral().lambdaStepNm();
        return (v == Variant.NMM && step == 5 || v == THESIS && step == 1) && isThesis(c);
    }

    private static boolean isThesis(BenchConfig c) {
        BrdfSettings s = c.settings();
        return s.taylor().highestOrder() == 30 && s.window().radius() == 1 && !s.window().automatic()
                && s.taylor().tolerance() == 0 && s.gpu().termFormat() == SweepPlan.EXACT_FORMAT;
    }

    private static Optional<BenchResult> find(List<BenchResult> results, Variant v, double stepNm) {
        return results.stream().filter(r -> r.config().settings().variant() == v
                && r.config().settings().spectral().lambdaStepNm() == stepNm && isThesis(r.config())).findFirst();
    }

    /** The markdown table of the outcomes. */
    public static String markdown(List<Outcome> outcomes) {
        StringBuilder b = new StringBuilder();
        b.append("| patch | FLSS thesis ms/frame (CIEDE2000) | auto choice at CIEDE2000 <= 2 | its ms/frame (CIEDE2000) |"
                + " speed-up | >= 10x | fastest at CIEDE2000 <= 1: ms/frame (CIEDE2000), speed-up |"
                + " NMM vs FLSS 1 nm: CIEDE2000 mean (p95) | NMM, FLSS 1 nm vs reference | <= 2 |\n");
        b.append("|---|---|---|---|---|---|---|---|---|---|\n");
        for (Outcome o : outcomes) {
            String choice = o.autoChoice().map(c -> AutoChoice.describe(c.chosen())).orElse("none meets it");
            String chosenNumbers = o.autoChoice().map(c -> String.format(Locale.ROOT, "%.2f (%.3f)",
                    c.chosen().msPerFrame(), c.chosen().deltaEMean())).orElse("-");
            String nmm = o.nmmVersusFlss1nm() == null ? "-" : String.format(Locale.ROOT, "%.3f (%.3f)",
                    o.nmmVersusFlss1nm().mean(), o.nmmVersusFlss1nm().p95());
            String nmmRef = o.nmm() == null || o.flss1nm() == null ? "-" : String.format(Locale.ROOT, "%.3f, %.3f",
                    o.nmm().deltaEMean(), o.flss1nm().deltaEMean());
            String speedUp = o.autoChoice().isEmpty() ? "-" : String.format(Locale.ROOT, "%.1f", o.speedUp());
            String close = o.closeChoice().map(c -> String.format(Locale.ROOT, "%s: %.2f (%.3f), %.1fx",
                    AutoChoice.describe(c.chosen()), c.chosen().msPerFrame(), c.chosen().deltaEMean(),
                    o.closeSpeedUp())).orElse("none");
            b.append(String.format(Locale.ROOT, "| %s | %.2f (%.3f) | %s | %s | %s | %s | %s | %s | %s | %s |%n",
                    o.patch(), o.flssThesis().msPerFrame(), o.flssThesis().deltaEMean(), choice, chosenNumbers,
                    speedUp, o.speedTargetMet() ? "yes" : "**no**", close, nmm, nmmRef,
                    o.nmmVersusFlss1nm() == null ? "-" : o.nmmTargetMet() ? "yes" : "**no**"));
        }
        return b.toString();
    }
}
