package diffract.bench;

import diffract.optics.BrdfSettings;
import diffract.optics.Variant;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The auto variant's choice rules on hand-made calibrations. */
class AutoChoiceTest {
    private static BenchResult result(int terms, double ms, double deltaE) {
        BrdfSettings s = BrdfSettings.thesis(Variant.FLSS).with(b -> b.highestOrder(terms));
        return new BenchResult(new BenchConfig("p", s, 64), ms, new MapError(deltaE, 2 * deltaE, deltaE / 10, 100));
    }

    @Test
    void picksTheCheapestThatMeetsTheTargetAndNamesTheNextCheaperRejected() {
        BenchResult exact = result(30, 100, 0.2);
        BenchResult good = result(16, 40, 1.5);
        BenchResult cheapButWrong = result(8, 20, 3.0);
        BenchResult cheapest = result(4, 5, 9.0);
        AutoChoice c = AutoChoice.choose(List.of(exact, cheapest, good, cheapButWrong), 2.0).orElseThrow();
        assertEquals(good, c.chosen());
        assertEquals(Optional.of(cheapButWrong), c.cheaperRejected());
        String why = c.explanation();
        assertTrue(why.contains("40.00 ms/frame") && why.contains("1.500") && why.contains("20.00 ms/frame")
                && why.contains("3.000 > 2"), why);
    }

    @Test
    void aTargetNothingMeetsChoosesNothingAndALaxOneTheCheapest() {
        List<BenchResult> all = List.of(result(30, 100, 0.2), result(4, 5, 9.0));
        assertTrue(AutoChoice.choose(all, 0.1).isEmpty());
        AutoChoice lax = AutoChoice.choose(all, 50).orElseThrow();
        assertEquals(5, lax.chosen().msPerFrame());
        assertTrue(lax.cheaperRejected().isEmpty());
        assertEquals(0.2, AutoChoice.mostAccurate(all).orElseThrow().deltaEMean());
    }

    @Test
    void ofEquallyCheapConfigurationsTheMoreAccurateAndNeverOneWithoutLitPixels() {
        BenchResult a = result(8, 10, 1.0);
        BenchResult b = result(16, 10, 0.5);
        BenchResult unlit = new BenchResult(new BenchConfig("p", BrdfSettings.thesis(Variant.NMM), 64), 1,
                new MapError(Double.NaN, Double.NaN, 0, 0));
        assertEquals(b, AutoChoice.choose(List.of(a, unlit, b), 2).orElseThrow().chosen());
    }

    /** On random calibrations: a stricter target never picks a larger measured error, nor a cheaper configuration. */
    @Test
    void aStricterTargetNeverPicksALargerMeasuredError() {
        Random random = new Random(11);
        for (int trial = 0; trial < 500; trial++) {
            List<BenchResult> calibration = new ArrayList<>();
            int n = 1 + random.nextInt(30);
            for (int i = 0; i < n; i++) {
                calibration.add(result(random.nextInt(40), 1 + random.nextInt(50), 10 * random.nextDouble()));
            }
            double lax = 10 * random.nextDouble();
            double strict = lax * random.nextDouble();
            Optional<AutoChoice> laxChoice = AutoChoice.choose(calibration, lax);
            Optional<AutoChoice> strictChoice = AutoChoice.choose(calibration, strict);
            if (strictChoice.isPresent()) {
                assertTrue(laxChoice.isPresent());
                assertTrue(strictChoice.get().chosen().deltaEMean() <= laxChoice.get().chosen().deltaEMean(),
                        "strict " + strict + " chose " + strictChoice.get().chosen() + ", lax " + lax + " chose "
                                + laxChoice.get().chosen());
                assertTrue(strictChoice.get().chosen().msPerFrame() >= laxChoice.get().chosen().msPerFrame());
                assertTrue(strictChoice.get().chosen().deltaEMean() <= strict);
            }
        }
    }
}
