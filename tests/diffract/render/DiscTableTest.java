package diffract.render;

import diffract.jrtr.textures.FloatTexture3D;
import diffract.optics.BakedGrid;
import diffract.optics.BrdfSettings;
import diffract.optics.settings.LightProfile;
import diffract.optics.Variant;
import org.junit.jupiter.api.Test;

import java.util.Arrays;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@link DiscTable}'s host side: each member is the table averaged over its round disc (a uniform table stays uniform,
 * a single cell becomes a disc of the member's radius with the cell's integral and the disc's variance rho^2 / 4), w
 * slices stay apart, member 0 is the table itself, and the grid and the choice between the spread table and the rows follow the disc's size.
 */
class DiscTableTest {
    private static final int N = 129;     // table samples per (u, v) axis: spacing 1/32
    private static final int NW = 3;
    private static final double HALF_ANGLE = Math.toRadians(15); // a 30-degree disc: sin R = 0.259, 8.3 samples

    @Test
    void aUniformTableStaysUniformAwayFromItsEdges() {
        float[] rgb = new float[3 * N * N * NW];
        Arrays.fill(rgb, 1f);
        DiscTable spread = DiscTable.of(table(rgb), HALF_ANGLE);
        int mid = spread.side() / 2;
        for (int m = 0; m < DiscTable.memberCos().length; m++) {
            for (int k = 0; k < NW; k++) {
                assertEquals(1.0, spread.xyzAt(m, mid, mid, k)[1], 1e-5, "member " + m + ", slice " + k);
            }
            if (m == 0) {
                continue; // the point member's disc lies within the edge cell: no strip beyond it
            }
            // beyond its edge cells (half a sample past |u| = 2) the table is zero (unreachable): a disc about the
            // edge holds half of it and the strip of width h / 2 beyond, h / (pi rho)
            double rho = DiscTable.memberRadiusUv(m, HALF_ANGLE, spread.side());
            double h = (BakedGrid.U_MAX - BakedGrid.U_MIN) / (N - 1);
            double edge = spread.xyzAt(m, 0, mid, 0)[1];
            assertEquals(0.5 + h / (Math.PI * rho), edge, 0.01, "member " + m + " at the table's edge");
        }
    }

    @Test
    void aSingleCellSpreadsIntoTheMembersRoundDisc() {
        double h = (BakedGrid.U_MAX - BakedGrid.U_MIN) / (N - 1);
        float[] rgb = new float[3 * N * N * NW];
        int centre = N / 2; // u = v = 0
        rgb[3 * (centre + N * (centre + N * 1)) + 1] = (float) (1 / (h * h)); // unit integral, slice 1
        DiscTable spread = DiscTable.of(table(rgb), HALF_ANGLE);
        int side = spread.side();
        double step = (BakedGrid.U_MAX - BakedGrid.U_MIN) / (side - 1);
        double[] cos = DiscTable.memberCos();
        assertEquals(0, cos[0], "member 0 is the point light's");
        assertEquals(N, side, "the point member keeps a 129-sample table's resolution");
        // the point member: the table itself, its sample at the cell and nothing around (a disc of half a step)
        assertEquals(1 / (h * h), spread.xyzAt(0, centre, centre, 1)[1], 1e-3 / (h * h), "the point member's cell");
        assertEquals(0, spread.xyzAt(0, centre + 1, centre, 1)[1], 1e-6, "the point member's neighbour");
        for (int m = 1; m < cos.length; m++) {
            double rho = DiscTable.memberRadiusUv(m, HALF_ANGLE, side);
            assertEquals(Math.sin(HALF_ANGLE) * cos[m], rho, 1e-15, "member " + m + "'s radius");
            double mass = 0;
            double second = 0;
            double inside = 0;
            int insideCount = 0;
            for (int j = 0; j < side; j++) {
                double v = BakedGrid.U_MIN + j * step;
                for (int i = 0; i < side; i++) {
                    double u = BakedGrid.U_MIN + i * step;
                    double value = spread.xyzAt(m, i, j, 1)[1];
                    double r = Math.hypot(u, v);
                    mass += value * step * step;
                    second += value * u * u * step * step;
                    if (r > rho + 2 * h) {
                        assertEquals(0, value, 1e-6, "member " + m + " beyond its disc at r = " + r);
                    }
                    if (r < rho - 2 * h) {
                        inside += value;
                        insideCount++;
                    }
                    assertEquals(0, spread.xyzAt(m, i, j, 0)[1], 0, "slices stay apart");
                }
            }
            assertEquals(1.0, mass, 0.02, "member " + m + ": the cell's integral is kept");
            // a round disc's variance per axis, rho^2 / 4, plus the cell's own, h^2 / 12 (a pooled cell's, 4 h^2 / 12)
            assertEquals(rho * rho / 4, second / mass, 0.03 * rho * rho / 4 + h * h / 3, "member " + m);
            assertEquals(1 / (Math.PI * rho * rho), inside / insideCount, 0.02 / (Math.PI * rho * rho),
                    "member " + m + ": uniform inside its disc");
        }
    }

    @Test
    void aCirclesSegmentsAreItsAreaBelowALine() {
        double rho = 0.3;
        assertEquals(0, DiscTable.segmentArea(-0.3, rho));
        assertEquals(Math.PI * rho * rho / 2, DiscTable.segmentArea(0, rho), 1e-15);
        assertEquals(Math.PI * rho * rho, DiscTable.segmentArea(0.31, rho));
        // the cap above y = rho / 2: rho^2 (pi / 3 - sqrt(3) / 4)
        assertEquals(rho * rho * (Math.PI / 3 - Math.sqrt(3) / 4),
                Math.PI * rho * rho - DiscTable.segmentArea(rho / 2, rho), 1e-15);
    }

    @Test
    void wideDiscsReadTheSpreadTableAndNarrowOnesTheRows() {
        BrdfSettings staged = BrdfSettings.thesis(Variant.BAKED).with(b -> b.lightSizeDeg(15)
                .lightProfile(LightProfile.DISC));
        BakedGrid grid = new BakedGrid(512, 25);
        assertTrue(DiscTable.applies(staged, grid), "the staged scenes' 15-degree key light");
        assertFalse(DiscTable.applies(staged.with(b -> b.lightSizeDeg(0.53)), grid), "the sun: 0.6 samples");
        assertFalse(DiscTable.applies(staged.with(b -> b.lightProfile(LightProfile.GAUSSIAN)), grid),
                "a Gaussian light is in the table already");
        assertEquals(DiscTable.MIN_SIDE, DiscTable.side(Math.toRadians(7.5), 512),
                "8 samples across sin 7.5 degrees (247) and half the table's for the point member");
        assertEquals(DiscTable.MIN_SIDE, DiscTable.side(Math.toRadians(60), 512), "8 samples across sin 60 degrees: 38");
        assertEquals(460, DiscTable.side(Math.toRadians(4), 512), "8 samples across sin 4 degrees");
        assertEquals(65, DiscTable.side(Math.toRadians(2), 65), "never finer than the table");
    }

    @Test
    void onlyAFilteredTableIsSpread() {
        BakedTable flss = new BakedTable(new BakedGrid(N, NW), new float[3 * N * N * NW],
                FloatTexture3D.Precision.FLOAT32, 0, Variant.FLSS, 0);
        assertThrows(IllegalArgumentException.class, () -> DiscTable.of(flss, HALF_ANGLE));
    }

    private static BakedTable table(float[] rgb) {
        return new BakedTable(new BakedGrid(N, NW), rgb, FloatTexture3D.Precision.FLOAT32, 0, Variant.LOBES, 0);
    }
}
