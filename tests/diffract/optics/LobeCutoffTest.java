package diffract.optics;

import diffract.colour.HatFilteredSpectrum;
import diffract.optics.patches.Direction;
import diffract.optics.illumination.Footprint;
import diffract.optics.illumination.LobeGeometry;
import diffract.optics.lobes.LobeWeightTable;
import diffract.optics.numerics.Covariance2;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.settings.PixelFilter;
import diffract.optics.spectra.TaylorTerms;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The lobes method's cutoff ({@link LobeQuadrature#cutoff}): the bound a lobe is skipped by is at least what the lobe
 * adds, the march over blocks of texels sums exactly the lobes the march over single texels sums, and the pieces of
 * the bound (the spectral density's range maxima, the wavelengths a box of lobe centres is within reach, the blocks'
 * weight bounds) hold what they claim. On a 50 um scan at 65 um (sigma_f = 0.49 texels), whose halo reaches every
 * pixel of a BRDF map.
 */
class LobeCutoffTest {
    /**
     * A point light, a light of 2 degrees' Gaussian (sigma D / 4) and a tilted elliptical Gaussian over a pixel, as
     * (u, v) covariances.
     */
    private static final Covariance2[] LIGHTS = {Covariance2.ZERO,
        Covariance2.isotropic(Math.pow(Math.toRadians(0.5), 2)), new Covariance2(4e-5, 2e-5, 6e-5)};
    private static HeightField scan;
    private static TaylorTerms terms;

    @BeforeAll
    static void scan() {
        scan = SyntheticPatches.elapheScan(128, 50, SyntheticPatches.ELAPHE_RIDGE_PERIOD_UM, 0.3, 3L).meanSubtracted();
        terms = TaylorTermComputer.compute(scan, 20, Reporter.SILENT);
    }

    private static LobeSpectrum lobes() {
        return lobes(LobeQuadrature.DEFAULT);
    }

    private static LobeSpectrum lobes(LobeQuadrature quadrature) {
        BrdfSettings settings = BrdfSettings.thesis(Variant.LOBES).with(b -> b.highestOrder(20)
                .pixelFilter(PixelFilter.BOX).lobes(quadrature.withSumNodesPerBox(0)));
        return DiffractionBrdf.create(settings, scan, terms).lobes();
    }

    /** Viewing directions over the upper hemisphere at theta_i = 30 degrees: (u, v, w) of a BRDF map's pixels. */
    private static double[][] pixels(int size) {
        Direction wi = Direction.fromSphericalDeg(30, 90);
        List<double[]> out = new java.util.ArrayList<>();
        for (int j = 0; j < size; j++) {
            for (int i = 0; i < size; i++) {
                double x = 2 * (i + 0.5) / size - 1;
                double y = 1 - 2 * (j + 0.5) / size;
                if (x * x + y * y < 1) {
                    double z = Math.sqrt(1 - x * x - y * y);
                    out.add(new double[] {-wi.x() - x, -wi.y() - y, -wi.z() - z});
                }
            }
        }
        return out.toArray(new double[0][]);
    }

    /**
     * Every lobe within reach of a pixel adds at most its bound, in every channel: over a 24 x 24 map's pixels (boxes
     * of 1/12 in u and v) under a point light, a light of 2 degrees' Gaussian and a tilted elliptical one, over a
     * hundred thousand lobes each. The bound is not idly wide: the lobes closest to theirs add a tenth of it and more, the median lobe a
     * ten-thousandth (most lobes within reach pass far from the footprint).
     */
    @Test
    void noLobeAddsMoreThanItsBound() {
        int size = 24;
        for (Covariance2 light : LIGHTS) {
            LobeSpectrum lobes = lobes();
            List<Double> ratios = new java.util.ArrayList<>();
            double worst = 0;
            for (double[] p : pixels(size)) {
                for (double[] lobe : lobes.lobeBounds(p[0], p[1], p[2], Footprint.mapPixel(size).plus(light))) {
                    if (lobe[0] > 0) {
                        worst = Math.max(worst, lobe[0] / lobe[1]);
                        ratios.add(lobe[0] / lobe[1]);
                    }
                }
            }
            java.util.Collections.sort(ratios);
            double median = ratios.get(ratios.size() / 2);
            String where = String.format(java.util.Locale.ROOT, "%s: %d lobes, contribution / bound at most %.3g, "
                    + "median %.3g", light, ratios.size(), worst, median);
            TestReport.line(LobeCutoffTest.class, where);
            assertTrue(ratios.size() > 10000, where);
            assertTrue(worst <= 1, where);
            assertTrue(worst > 0.1 && median > 1e-4, where);
        }
    }

    /**
     * Skipping blocks of texels by their bound leaves the sum unchanged: the map marched in blocks, by rows or by the
     * texels' bounds, equals the same marched texel by texel to rounding (the order of the sum differs), at the
     * default cutoff and at a bright display's (where most blocks go by rows).
     */
    @Test
    void theBlocksSkipOnlyLobesTheCutoffSkips() {
        long byRows = 0;
        long byBound = 0;
        for (LobeQuadrature quadrature : new LobeQuadrature[] {LobeQuadrature.DEFAULT,
            LobeQuadrature.DEFAULT.shownAt(3.5e4)}) {
            LobeSpectrum blocks = lobes(quadrature);
            assertSameSums(blocks, lobes(quadrature).withoutBlocks());
            byRows += blocks.blocksByRows.sum();
            byBound += blocks.blocksByBound.sum();
        }
        TestReport.printf(LobeCutoffTest.class, "blocks marched by rows %d, by bounds %d%n", byRows, byBound);
        assertTrue(byRows > 0 && byBound > 0, "both ways are taken: " + byRows + " by rows, " + byBound + " by bounds");
    }

    private static void assertSameSums(LobeSpectrum blocks, LobeSpectrum texels) {
        int size = 24;
        for (Covariance2 light : LIGHTS) {
            double worst = 0;
            double total = 0;
            for (double[] p : pixels(size)) {
                Footprint footprint = Footprint.mapPixel(size).plus(light);
                double[] a = blocks.xyz(p[0], p[1], p[2], footprint);
                double[] b = texels.xyz(p[0], p[1], p[2], footprint);
                for (int c = 0; c < 3; c++) {
                    worst = Math.max(worst, Math.abs(a[c] - b[c]));
                    total = Math.max(total, a[c]);
                }
            }
            assertTrue(total > 1e-3, "the map is lit: " + total);
            assertTrue(worst <= 1e-12 * total, light + ", blocks against texels: " + worst + " of " + total);
        }
    }

    /**
     * The spectral density's range maximum over a passage is the largest weight per nanometre of the passage's nodes
     * at every spacing the quadrature takes (0.37 nm to 16 nm), and no more than the table's largest entry over the
     * passage widened by its last node; a whole grid of nodes sums to at most the band's weight.
     */
    @Test
    void theDensityBoundHoldsEveryNodeOfAPassage() {
        HatFilteredSpectrum density = new HatFilteredSpectrum(380, 780);
        double[] out = new double[3];
        java.util.Random random = new java.util.Random(5);
        for (int trial = 0; trial < 2000; trial++) {
            double from = 380 + 400 * random.nextDouble();
            double to = Math.min(780, from + 200 * Math.pow(random.nextDouble(), 3));
            double bound = density.maxDensity(from, to);
            for (double spacing : new double[] {0.37, 1, 2, 4, 8, 16}) {
                for (int j = (int) Math.ceil((from - 380) / spacing - 1e-9); 380 + j * spacing <= to + spacing; j++) {
                    density.weight(380 + j * spacing, spacing, out);
                    for (double v : out) {
                        assertTrue(v / spacing <= bound * (1 + 1e-12), from + ".." + to + " nm at " + spacing);
                    }
                }
            }
            assertTrue(bound <= density.maxDensity(), "no more than the band's");
        }
        assertEquals(density.maxDensity(380, 780), density.maxDensity(), 0);
        // a whole grid's weights, in every channel, are within the band's weight (and near it: the hats sum to one)
        for (double spacing : new double[] {0.37, 1, 2, 4, 8, 16}) {
            double[] sum = new double[3];
            for (int j = 0; 380 + j * spacing <= 780 + spacing; j++) {
                density.weight(380 + j * spacing, spacing, out);
                for (int c = 0; c < 3; c++) {
                    sum[c] += out[c];
                }
            }
            double largest = Math.max(sum[0], Math.max(sum[1], sum[2]));
            assertTrue(largest <= density.bandWeight() && largest >= 0.95 * density.bandWeight(),
                    spacing + " nm: " + largest + " against " + density.bandWeight());
        }
        // narrow passages see the density where they are: in the red tail far less than the blue's peak of z
        assertTrue(density.maxDensity(700, 702) < 0.1 * density.maxDensity());
    }

    /**
     * The wavelengths at which a box of lobe centres comes within reach hold those of every centre in the box, and,
     * for a box of one centre, are that centre's.
     */
    @Test
    void aBoxOfCentresIsWithinReachWhereverOneOfItsCentresIs() {
        java.util.Random random = new java.util.Random(11);
        for (int trial = 0; trial < 20000; trial++) {
            double cx0 = 4 * random.nextDouble() - 2;
            double cy0 = 4 * random.nextDouble() - 2;
            double cx1 = cx0 + 0.3 * random.nextDouble();
            double cy1 = cy0 + 0.3 * random.nextDouble();
            double u = 2 * random.nextDouble() - 1;
            double v = 2 * random.nextDouble() - 1;
            double reach = 0.05 * random.nextDouble();
            double[] box = LobeGeometry.boxLambdaIntervalNm(cx0, cx1, cy0, cy1, u, v, reach, reach, 380, 780);
            for (int k = 0; k < 8; k++) {
                double cx = cx0 + (cx1 - cx0) * random.nextDouble();
                double cy = cy0 + (cy1 - cy0) * random.nextDouble();
                double[] one = LobeGeometry.lambdaIntervalNm(cx, cy, u, v, reach, reach, 380, 780);
                if (one != null) {
                    assertTrue(box != null && box[0] <= one[0] && one[1] <= box[1], "centre in the box");
                }
            }
            double[] point = LobeGeometry.boxLambdaIntervalNm(cx0, cx0, cy0, cy0, u, v, reach, reach, 380, 780);
            double[] one = LobeGeometry.lambdaIntervalNm(cx0, cy0, u, v, reach, reach, 380, 780);
            assertEquals(one == null, point == null, "a box of one centre");
            if (one != null) {
                assertEquals(one[0], point[0], 1e-6);
                assertEquals(one[1], point[1], 1e-6);
            }
        }
    }

    /**
     * A block's order lists each of its texels in the grid once, from the largest bound over all bins down, each with
     * that bound, and then the end marker.
     */
    private static void assertOrdered(LobeWeightTable table, int bc, int br) {
        int block = LobeWeightTable.BLOCK;
        int texels = (Math.min(table.rows(), (br + 1) * block) - br * block)
                * (Math.min(table.cols(), (bc + 1) * block) - bc * block);
        java.util.Set<Integer> seen = new java.util.HashSet<>();
        double previous = Double.POSITIVE_INFINITY;
        for (int slot = 0; slot < block * block; slot++) {
            int offset = table.orderedTexel(bc, br, slot);
            if (slot >= texels) {
                assertEquals(-1, offset, "past the block's last texel");
                continue;
            }
            int col = bc * block + offset % block;
            int row = br * block + offset / block;
            assertTrue(seen.add(offset) && col < table.cols() && row < table.rows(), "slot " + slot);
            double largest = table.bound(col, row, 0, table.maxPhasePerUm());
            assertEquals(largest, table.orderedBound(bc, br, slot), 1e-7 * largest);
            assertTrue(largest <= previous, "descending at slot " + slot);
            previous = largest;
        }
    }

    /**
     * A block's bound in every bin is the largest of its texels' (so a block skipped holds no texel that reaches), and
     * its texels' order is from the largest bound down.
     */
    @Test
    void aBlocksBoundIsItsTexelsLargest() {
        LobeWeightTable table = LobeWeightTable.ofTerms(terms, 20, 380, 1e-4);
        double p = table.maxPhasePerUm();
        for (int bin = 0; bin < LobeWeightTable.BINS; bin++) {
            double lo = bin * p / LobeWeightTable.BINS + 1e-9;
            double hi = (bin + 1) * p / LobeWeightTable.BINS - 1e-9;
            for (int br = 0; br < table.blockRows(); br++) {
                for (int bc = 0; bc < table.blockCols(); bc++) {
                    double largest = 0;
                    for (int r = br * LobeWeightTable.BLOCK; r < Math.min(table.rows(), (br + 1) * LobeWeightTable.BLOCK); r++) {
                        for (int c = bc * LobeWeightTable.BLOCK; c < Math.min(table.cols(), (bc + 1) * LobeWeightTable.BLOCK); c++) {
                            largest = Math.max(largest, table.bound(c, r, lo, hi));
                        }
                    }
                    assertEquals(largest, table.blockBound(bc, br, lo, hi), 0, "block " + bc + ", " + br);
                    if (bin == 0) {
                        assertOrdered(table, bc, br);
                    }
                }
            }
        }
    }
}
