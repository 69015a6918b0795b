package diffract.bench;

import diffract.optics.BrdfSettings;
import diffract.optics.Variant;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** What the sweeps hold: the lean points (early stop, automatic window), the baked table once per patch. */
class SweepPlanTest {
    private static final BrdfSettings BASE = BrdfSettings.thesis(Variant.FLSS).with(b -> b.coherenceLengthUm(4 * (2.5)));

    @Test
    void theQuickSweepMeasuresTheLeanThesisPointAgainstTheFixedOneAndLeavesTheBakeOut() {
        List<Variant> quick = SweepPlan.sweptVariants(true);
        assertFalse(quick.contains(Variant.BAKED), "the bake alone would exceed the quick budget");
        assertTrue(SweepPlan.sweptVariants(false).contains(Variant.BAKED));
        List<BenchConfig> configs = SweepPlan.configs(List.of("p"), List.of(Variant.FLSS), SweepPlan.quick(64), BASE);
        BenchConfig fixed = find(configs, 30, 5, 0.0);
        BenchConfig lean = find(configs, 30, 5, SweepPlan.LEAN_TAYLOR_TOLERANCE);
        assertEquals("1", fixed.windowRadiusLabel());
        assertEquals("auto", lean.windowRadiusLabel());
        assertTrue(lean.settings().window().automatic());
        assertFalse(fixed.key().equals(lean.key()), "the lean point is a configuration of its own");
    }

    @Test
    void theBakedTableIsMeasuredOncePerPatchAndSizeAtTheThesisPoint() {
        List<SweepPlan.Point> full = SweepPlan.full(64, 128);
        List<BenchConfig> baked = SweepPlan.configs(List.of("a", "b"), List.of(Variant.BAKED), full, BASE);
        assertEquals(4, baked.size(), "2 patches x 2 sizes");
        for (BenchConfig c : baked) {
            assertEquals(30, c.settings().taylor().highestOrder());
            assertEquals(5, c.settings().spectral().lambdaStepNm());
            assertEquals(0, c.settings().taylor().tolerance());
            assertEquals(SweepPlan.EXACT_FORMAT, c.settings().gpu().termFormat());
        }
    }

    /** The calibration cache reads results.csv back: an automatic window and a tolerance survive the round trip. */
    @Test
    void leanConfigurationsSurviveTheCsvRoundTrip(@TempDir Path dir) throws IOException {
        List<BenchConfig> configs = SweepPlan.configs(List.of("p"), List.of(Variant.FLSS, Variant.PQ),
                SweepPlan.quick(64), BASE);
        List<BenchResult> results = configs.stream()
                .map(c -> new BenchResult(c, c.workUnits() * 1e-9, new MapError(1.5, 3, 0.2, 40))).toList();
        Path csv = dir.resolve("results.csv");
        ResultsTable.writeCsv(csv, results);
        List<BenchResult> read = ResultsTable.readCsv(csv, BASE);
        assertEquals(results.size(), read.size());
        for (int i = 0; i < results.size(); i++) {
            assertEquals(results.get(i).config().key(), read.get(i).config().key());
            assertEquals(results.get(i).config().settings().window().automatic(),
                    read.get(i).config().settings().window().automatic());
        }
    }

    private static BenchConfig find(List<BenchConfig> configs, int n, double stepNm, double tolerance) {
        return configs.stream().filter(c -> c.settings().taylor().highestOrder() == n && c.settings().spectral().lambdaStepNm() == stepNm
                && c.settings().taylor().tolerance() == tolerance && c.settings().gpu().termFormat() == SweepPlan.EXACT_FORMAT)
                .findFirst().orElseThrow();
    }
}
