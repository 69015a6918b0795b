package diffract.optics.baked;

import diffract.colour.MirrorNormalisation;
import diffract.colour.Srgb;
import diffract.colour.Xyz;
import diffract.optics.BakedGrid;
import diffract.optics.BrdfMap;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.Variant;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.settings.PixelFilter;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The exported table against the lobes method's BRDF evaluated directly: exact at its nodes, between nodes within
 * the nodes' range, and as a BRDF map equal to {@code brdfmap}'s where the map's pixels are the table's cells.
 */
class BrdfTableTest {
    /** 129 nodes along u and v: a spacing of 4 / 128 = 2 / 64, one pixel of a 64 x 64 map. */
    private static final BakedGrid GRID = new BakedGrid(129, 9);
    private static final int MAP_PX = 64;
    private static DiffractionBrdf brdf;
    private static BrdfTable table;

    @BeforeAll
    static void tabulate() {
        HeightField patch = SyntheticPatches.blazed(2.5, 0.2, 20, 4, 16).meanSubtracted();
        BrdfSettings thesis = BrdfSettings.thesis(Variant.LOBES).with(b -> b.pixelFilter(PixelFilter.BOX));
        BrdfSettings settings = thesis.with(b -> b.spectral(thesis.spectral()
                .withNormalisation(MirrorNormalisation.ENERGY)));
        brdf = DiffractionBrdf.create(settings, patch, TaylorTermComputer.compute(patch, 30, Reporter.SILENT));
        table = BrdfTable.of(brdf, GRID, Reporter.SILENT);
    }

    private static double[] direct(double u, double v, double w) {
        double[] xyz = brdf.lobes().xyz(u, v, w, BrdfTable.cellFootprint(GRID));
        return Srgb.linearFromXyz(new Xyz(xyz[0], xyz[1], xyz[2]));
    }

    @Test
    void nodesHoldTheLobesMethodAveragedOverTheirCell() {
        Random random = new Random(7);
        int checked = 0;
        double brightest = 0;
        for (int s = 0; s < 400; s++) {
            int i = random.nextInt(GRID.uvSamples());
            int j = random.nextInt(GRID.uvSamples());
            int k = random.nextInt(GRID.wSamples());
            double u = GRID.uv(i);
            double v = GRID.uv(j);
            double w = GRID.w(k);
            if (!BrdfTable.nearReachable(GRID, u, v, w)) {
                continue;
            }
            double[] expected = direct(u, v, w);
            double[] node = table.node(i, j, k);
            double[] at = table.at(u, v, w);
            for (int c = 0; c < 3; c++) {
                double tolerance = 1e-6 * Math.abs(expected[c]) + 1e-12;
                assertEquals(expected[c], node[c], tolerance, "node " + i + "," + j + "," + k);
                assertEquals(node[c], at[c], tolerance, "lookup at node " + i + "," + j + "," + k);
                brightest = Math.max(brightest, expected[c]);
            }
            checked++;
        }
        assertTrue(checked > 100, "too few reachable nodes checked: " + checked);
        assertTrue(brightest > 0, "every checked node is dark");
    }

    @Test
    void betweenNodesTheLookupStaysWithinItsEightNodes() {
        Random random = new Random(11);
        for (int s = 0; s < 2000; s++) {
            double fu = random.nextDouble() * (GRID.uvSamples() - 1);
            double fv = random.nextDouble() * (GRID.uvSamples() - 1);
            double fw = random.nextDouble() * (GRID.wSamples() - 1);
            int i = (int) fu;
            int j = (int) fv;
            int k = (int) fw;
            double[] at = table.at(BakedGrid.U_MIN + fu * 4.0 / (GRID.uvSamples() - 1),
                    BakedGrid.U_MIN + fv * 4.0 / (GRID.uvSamples() - 1), BakedGrid.W_MIN + fw * 2.0 / (GRID.wSamples() - 1));
            for (int c = 0; c < 3; c++) {
                double lo = Double.POSITIVE_INFINITY;
                double hi = Double.NEGATIVE_INFINITY;
                for (int corner = 0; corner < 8; corner++) {
                    double value = table.node(i + (corner & 1), j + (corner >> 1 & 1), k + (corner >> 2 & 1))[c];
                    lo = Math.min(lo, value);
                    hi = Math.max(hi, value);
                }
                double slack = 1e-6 * Math.max(Math.abs(lo), Math.abs(hi)) + 1e-12;
                assertTrue(at[c] >= lo - slack && at[c] <= hi + slack, "lookup outside its nodes at " + fu + ","
                        + fv + "," + fw);
            }
        }
    }

    /**
     * With the light placed so that every pixel centre of a 64 x 64 map lands on a node in (u, v), and the cell equal
     * to the pixel, the table's relative BRDF is brdfmap's pixel (DiffractionBrdf#mapPixel) up to the interpolation
     * along w, which varies only through the Taylor phase.
     */
    @Test
    void aMapFromTheTableIsBrdfMapsWhereCellsArePixels() {
        Direction wi = Direction.fromProjected(17.0 / MAP_PX, 33.0 / MAP_PX); // (u, v) of pixel centres on nodes
        double brightest = 0;
        double worst = 0;
        int lit = 0;
        for (int row = 0; row < MAP_PX; row++) {
            for (int col = 0; col < MAP_PX; col++) {
                double x = BrdfMap.xOf(col, MAP_PX);
                double y = BrdfMap.yOf(row, MAP_PX);
                if (x * x + y * y >= 1) {
                    continue;
                }
                Direction wr = Direction.fromProjected(x, y);
                double fu = (-wi.x() - x - BakedGrid.U_MIN) / 4.0 * (GRID.uvSamples() - 1);
                assertEquals(Math.rint(fu), fu, 1e-9, "pixel centre off the nodes");
                double[] expected = Srgb.linearFromXyz(brdf.mapPixel(wi, col, row, MAP_PX));
                double[] got = table.relative(wi, wr);
                for (int c = 0; c < 3; c++) {
                    brightest = Math.max(brightest, Math.abs(expected[c]));
                    worst = Math.max(worst, Math.abs(got[c] - expected[c]));
                }
                lit += expected[1] > 1e-5 ? 1 : 0;
            }
        }
        System.out.printf(java.util.Locale.ROOT, "table against brdfmap's pixels: largest difference %.3g of the"
                + " brightest %.3g (%.2f %%), %d lit pixels%n", worst, brightest, 100 * worst / brightest, lit);
        assertTrue(lit > 20, "the map shows too little light to compare: " + lit + " pixels");
        assertTrue(worst <= 0.02 * brightest, "the table's map differs by " + worst + " of " + brightest);
    }
}
