package diffract.optics;

import diffract.optics.patches.Direction;
import diffract.optics.lobes.LobeWeightTable;
import diffract.optics.maps.AutoExposure;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.settings.PixelFilter;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.windows.CoherenceWindow;
import diffract.optics.windows.WindowPlacement;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import java.util.List;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The lobes' texel sums: a box's sum against the texels' weights summed one by one with their cells' overlaps (boxes
 * inside a quadrant, across the origin's axes and beyond the grid), the spread's mass, mean and variance against a
 * lobe's, what the estimate before the work says it takes, and where the sums apply.
 */
class LobeSumTableTest {
    private static final double PHASE_PER_UM = 7.3;

    private static TaylorTerms terms() {
        HeightField patch = WideScan.of(36, 0.5);
        return TaylorTermComputer.compute(patch, 20, Reporter.SILENT);
    }

    /** With lobes as wide as a cell (no kernel), a box's sum is sum_m W_m(a) |box &#8745; cell_m| exactly. */
    @Test
    void aBoxSumsTheWeightsOfTheCellsItCovers() {
        TaylorTerms terms = terms();
        LobeWeightTable weights = LobeWeightTable.ofTerms(terms, 20, 380, 1e-4);
        LobeSumTable sums = new LobeSumTable(weights, LobeSumTable.MIN_SIGMA_TEXELS, LobeSumTable.MIN_SIGMA_TEXELS);
        int rows = weights.rows();
        int cols = weights.cols();
        Random random = new Random(3);
        double worst = 0;
        for (int trial = 0; trial < 400; trial++) {
            double a = -random.nextDouble() * weights.maxPhasePerUm();
            // boxes anywhere from one cell to beyond the grid, often across an axis through the origin
            double cx = (random.nextDouble() - 0.5) * (cols + 6);
            double cy = (random.nextDouble() - 0.5) * (rows + 6);
            double wx = random.nextDouble() * (trial % 4 == 0 ? cols : 4);
            double wy = random.nextDouble() * (trial % 4 == 1 ? rows : 4);
            double x0 = cx - wx / 2;
            double x1 = cx + wx / 2;
            double y0 = cy - wy / 2;
            double y1 = cy + wy / 2;
            double expected = 0;
            double largest = 0;
            for (int row = 0; row < rows; row++) {
                for (int col = 0; col < cols; col++) {
                    int mx = col - cols / 2;
                    int my = row - rows / 2;
                    double w = weights.weight(col, row, a);
                    largest += w;
                    expected += w * overlap(x0, x1, mx) * overlap(y0, y1, my);
                }
            }
            double got = sums.boxSum(x0, x1, y0, y1, a);
            // float32 sums: rounding relative to the grid's total, which bounds every tail
            worst = Math.max(worst, Math.abs(got - expected) / largest);
            assertEquals(expected, got, 1e-6 * largest, "box [" + x0 + ", " + x1 + "] x [" + y0 + ", " + y1 + "]");
        }
        TestReport.line(LobeSumTableTest.class, String.format(java.util.Locale.ROOT,
                "box sums against the cells one by one: worst %.1e of the grid's total over 400 boxes", worst));
    }

    /**
     * Each texel's spread has a lobe's mean and variance, sigma_f^2 / 2 per axis, and keeps its mass: in cells of one
     * texel (sigma_f = 1.3) and of two (sigma_f = 2.0, a 200 um scan's lobes at 65 um), read from strips a tenth of a
     * texel wide.
     */
    @ParameterizedTest
    @CsvSource({"1.3, 1", "2.0, 2"})
    void theSpreadHasTheLobesMassMeanAndVariance(double sigma, int cellTexels) {
        TaylorTerms terms = terms();
        LobeWeightTable weights = LobeWeightTable.ofTerms(terms, 20, 380, 1e-4);
        LobeSumTable sums = new LobeSumTable(weights, sigma, sigma);
        assertEquals(cellTexels, sums.cellTexels());
        int rows = weights.rows();
        int cols = weights.cols();
        double a = -PHASE_PER_UM;
        // the x-marginal of the weights
        double mass = 0;
        double mean = 0;
        double square = 0;
        for (int col = 0; col < cols; col++) {
            double column = 0;
            for (int row = 0; row < rows; row++) {
                column += weights.weight(col, row, a);
            }
            int mx = col - cols / 2;
            mass += column;
            mean += mx * column;
            square += (double) mx * mx * column;
        }
        // the spread's, from narrow strips (their own width adds 0.1^2 / 12 to the variance)
        double strip = 0.1;
        double spreadMass = 0;
        double spreadMean = 0;
        double spreadSquare = 0;
        for (double x = -cols / 2.0 - 12; x < cols / 2.0 + 12; x += strip) {
            double inStrip = sums.boxSum(x, x + strip, -rows, rows, a);
            double centre = x + strip / 2;
            spreadMass += inStrip;
            spreadMean += centre * inStrip;
            spreadSquare += centre * centre * inStrip;
        }
        double variance = square / mass - Math.pow(mean / mass, 2);
        double spreadVariance = spreadSquare / spreadMass - Math.pow(spreadMean / spreadMass, 2) - strip * strip / 12;
        // the kernel's mass beyond the grid's edges (this small patch's spectrum reaches them), float32 sums
        assertEquals(mass, spreadMass, 2e-3 * mass);
        assertEquals(mean / mass, spreadMean / spreadMass, 2e-3);
        assertEquals(variance + 0.5 * sigma * sigma, spreadVariance, 3e-3 * (variance + sigma * sigma));
    }

    /** The heap the table takes is what the estimate before the work says. */
    @Test
    void theEstimateIsTheTable() {
        TaylorTerms terms = terms();
        LobeWeightTable weights = LobeWeightTable.ofTerms(terms, 20, 380, 1e-4);
        LobeSumTable sums = new LobeSumTable(weights, 0.6, 0.9);
        List<float[]> layers = sums.layers();
        long bytes = 0;
        for (float[] layer : layers) {
            bytes += 4L * layer.length;
        }
        assertEquals(bytes, LobeSumTable.bytes(terms.rows(), terms.cols(), weights.samples(), 0.6, 0.9));
        assertEquals(4L * sums.width() * sums.height(), layers.get(0).length);
    }

    /**
     * The sums apply where a lobe is at least as wide as a cell (the averaged window, sigma_f &gt;= 1 / sqrt(6)
     * texels): from a 41.7 um scan on at 65 um, never to the thesis' patches, nor with the window fixed or sums off.
     */
    @Test
    void theSumsApplyToScansWiderThanTwoThirdsOfTheCoherenceLength() {
        BrdfSettings settings = BrdfSettings.thesis(Variant.LOBES);
        CoherenceWindow window = settings.coherenceWindow();
        LobeQuadrature q = LobeQuadrature.DEFAULT;
        double widest = LobeSumTable.MIN_SIGMA_TEXELS / window.sigmaFrequencyPerUm();
        assertEquals(41.7, widest, 0.1);
        assertTrue(LobeSumTable.applies(window, q, 52.4, 50.8));
        assertFalse(LobeSumTable.applies(window, q, 52.4, 15.5), "one axis narrower than a cell's lobe");
        assertFalse(LobeSumTable.applies(window, q, 15.5, 15.5), "the thesis' tall patch");
        assertFalse(LobeSumTable.applies(window, q.withSumNodesPerBox(0), 52.4, 50.8));
        BrdfSettings fixed = settings.with(b -> b.windowPlacement(WindowPlacement.FIXED));
        assertFalse(LobeSumTable.applies(fixed.coherenceWindow(), q, 52.4, 50.8));
        LobeWeightTable weights = LobeWeightTable.ofTerms(terms(), 20, 380, 1e-4);
        assertThrows(IllegalArgumentException.class, () -> new LobeSumTable(weights, 0.3, 0.6));
    }

    /**
     * On a 50 um scan at 65 um (sigma_f = 0.49 texels) the texel sums draw the BRDF map of the lobes marched one by
     * one without a cutoff: lit mean CIEDE2000 0.43, p95 1.7 at 32 x 32 (a pixel's box 6 texels wide, nodes 8 nm
     * apart), the map's energy to 0.1 %. Lobes 1.4 times as wide (a coherence length of 45 um) fail the bound.
     */
    @Test
    void theSumsDrawTheMarchedLobesOfAScanWiderThanTheWindow() {
        HeightField scan = SyntheticPatches.elapheScan(512, 50, SyntheticPatches.ELAPHE_RIDGE_PERIOD_UM, 0.3, 1L)
                .meanSubtracted();
        TaylorTerms terms = TaylorTermComputer.compute(scan, 20, Reporter.SILENT);
        Direction wi = Direction.fromSphericalDeg(30, 90);
        int size = 32;
        BrdfSettings base = BrdfSettings.thesis(Variant.LOBES).with(b -> b.highestOrder(20)
                .pixelFilter(PixelFilter.BOX));
        LobeQuadrature d = LobeQuadrature.DEFAULT;
        LobeQuadrature exhaustive = new LobeQuadrature(d.pairThreshold(), d.nodesPerSigma(), d.maxStepNm(), 8,
                d.weightStepNm(), d.lightNodes(), 0, d.weightTolerance(), 0);
        DiffractionBrdf marched = DiffractionBrdf.create(base.with(b -> b.lobes(exhaustive)), scan, terms);
        DiffractionBrdf summed = DiffractionBrdf.create(base, scan, terms);
        float[] reference = BrdfMap.xyz(marched, wi, size, Reporter.SILENT);
        float[] sums = BrdfMap.xyz(summed, wi, size, Reporter.SILENT);
        BrdfMapDifference difference = difference(reference, sums, size, wi);
        double energy = total(sums) / total(reference);
        String where = difference.summary() + String.format(java.util.Locale.ROOT, ", energy %.5f", energy);
        TestReport.line(LobeSumTableTest.class, "50 um scan, 32 x 32, texel sums against the lobes marched: " + where);
        assertTrue(difference.lit().mean() <= 0.6 && difference.lit().p95() <= 2.2, where);
        assertEquals(1, energy, 2e-3, where);

        BrdfSettings wider = base.with(b -> b.coherenceLengthUm(45));
        float[] wrong = BrdfMap.xyz(DiffractionBrdf.create(wider, scan, terms), wi, size, Reporter.SILENT);
        BrdfMapDifference control = difference(reference, wrong, size, wi);
        TestReport.line(LobeSumTableTest.class, "the same at 45 um: " + control.summary());
        assertTrue(control.lit().mean() > 0.6, "lobes 1.4 times as wide: " + control.summary());
    }

    private static BrdfMapDifference difference(float[] reference, float[] other, int size, Direction wi) {
        return BrdfMapDifference.of(reference, other, size, AutoExposure.ofXyz(reference, wi, size));
    }

    private static double total(float[] xyz) {
        double sum = 0;
        for (int p = 1; p < xyz.length; p += 3) {
            sum += xyz[p];
        }
        return sum;
    }

    /** |[lo, hi] &#8745; [m - 1/2, m + 1/2]|. */
    private static double overlap(double lo, double hi, int m) {
        return Math.max(0, Math.min(hi, m + 0.5) - Math.max(lo, m - 0.5));
    }
}
