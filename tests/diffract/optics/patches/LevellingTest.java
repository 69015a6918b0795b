package diffract.optics.patches;

import org.junit.jupiter.api.Test;

import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

class LevellingTest {
    private static final int ROWS = 12;
    private static final int COLS = 17;

    /**
     * A cosine centred on the grid, cos(2 pi k (c - (C - 1) / 2) / C), is orthogonal to 1, x and y on it: the
     * least-squares plane of the sinusoid alone is 0, so levelling must give the sinusoid back exactly.
     */
    private static double sinusoidUm(int r, int c) {
        return profileUm(c) + 0.02 * Math.cos(2 * Math.PI * 2 * (r - (ROWS - 1) / 2.0) / ROWS);
    }

    /** Ridges along y: a zero-mean cosine across the columns. */
    private static double profileUm(int c) {
        return 0.05 * Math.cos(2 * Math.PI * 3 * (c - (COLS - 1) / 2.0) / COLS);
    }

    private static HeightField field(Height height) {
        double[] h = new double[ROWS * COLS];
        for (int r = 0; r < ROWS; r++) {
            for (int c = 0; c < COLS; c++) {
                h[r * COLS + c] = height.at(r, c);
            }
        }
        return HeightField.of(ROWS, COLS, h, 0.05, 0.08);
    }

    private interface Height {
        double at(int r, int c);
    }

    @Test
    void planeRemovesATiltAndAnOffsetAndLeavesTheSinusoid() {
        // 0.7 um offset, a tilt of 0.013 um per column and -0.021 um per row: 0.2 and 0.23 um across the patch,
        // taller than the structure (peak to valley 0.14 um)
        HeightField tilted = field((r, c) -> 0.7 + 0.013 * c - 0.021 * r + sinusoidUm(r, c));
        HeightField levelled = Levelling.PLANE.apply(tilted);
        assertEquals(ROWS, levelled.rows());
        assertEquals(COLS, levelled.cols());
        assertEquals(0.05, levelled.pixelSizeXUm());
        assertEquals(0.08, levelled.pixelSizeYUm());
        for (int r = 0; r < ROWS; r++) {
            for (int c = 0; c < COLS; c++) {
                assertEquals(sinusoidUm(r, c), levelled.heightUm(r, c), 1e-12, "row " + r + ", column " + c);
            }
        }
    }

    @Test
    void planeLeavesResidualsWithoutMeanOrSlopeOnAnyField() {
        Random random = new Random(7);
        HeightField rough = field((r, c) -> random.nextGaussian() * 0.1 + 0.3 * c * c / COLS);
        HeightField levelled = Levelling.PLANE.apply(rough);
        double sum = 0;
        double sumX = 0;
        double sumY = 0;
        for (int r = 0; r < ROWS; r++) {
            for (int c = 0; c < COLS; c++) {
                sum += levelled.heightUm(r, c);
                sumX += (c - (COLS - 1) / 2.0) * levelled.heightUm(r, c);
                sumY += (r - (ROWS - 1) / 2.0) * levelled.heightUm(r, c);
            }
        }
        // the normal equations of the least-squares plane: the residual is orthogonal to 1, x and y
        assertEquals(0, sum, 1e-12);
        assertEquals(0, sumX, 1e-11);
        assertEquals(0, sumY, 1e-11);
        // and levelling a levelled field changes nothing
        HeightField twice = Levelling.PLANE.apply(levelled);
        for (int i = 0; i < ROWS * COLS; i++) {
            assertEquals(levelled.heightUm(i / COLS, i % COLS), twice.heightUm(i / COLS, i % COLS), 1e-14);
        }
    }

    @Test
    void rowsRemovesEachScanLinesOffset() {
        double[] offsetsUm = new double[ROWS];
        for (int r = 0; r < ROWS; r++) {
            offsetsUm[r] = 0.1 * r * r - 0.4 + (r % 3) * 0.07; // a scanner's drift with jumps
        }
        // along each row the same zero-mean profile; the rows differ only by their offsets
        HeightField striped = field((r, c) -> offsetsUm[r] + profileUm(c));
        HeightField levelled = Levelling.ROWS.apply(striped);
        for (int r = 0; r < ROWS; r++) {
            for (int c = 0; c < COLS; c++) {
                assertEquals(profileUm(c), levelled.heightUm(r, c), 1e-12, "row " + r + ", column " + c);
            }
        }
    }

    @Test
    void rowsKeepsWhatVariesAlongY() {
        // rows levelling removes per-row constants only: a tilt along x stays, a tilt along y goes
        HeightField tilted = field((r, c) -> 0.01 * c + 0.03 * r);
        HeightField levelled = Levelling.ROWS.apply(tilted);
        for (int r = 0; r < ROWS; r++) {
            for (int c = 0; c < COLS; c++) {
                assertEquals(0.01 * (c - (COLS - 1) / 2.0), levelled.heightUm(r, c), 1e-14);
            }
        }
    }

    @Test
    void noneIsTheFieldAsRead() {
        HeightField field = field((r, c) -> 0.7 + 0.013 * c);
        assertSame(field, Levelling.NONE.apply(field));
    }

    @Test
    void labelsAreTheSpellingsOfTheCommandLineAndScenes() {
        assertEquals("plane", Levelling.PLANE.label());
        assertEquals(Levelling.ROWS, Levelling.fromLabel("rows"));
        assertEquals(Levelling.NONE, Levelling.fromLabel("none"));
        assertNull(Levelling.fromLabel("Plane"));
        assertEquals(Levelling.PLANE, Levelling.defaultFor(true));
        assertEquals(Levelling.NONE, Levelling.defaultFor(false));
    }

    @Test
    void aSingleRowOrColumnKeepsItsOtherSlope() {
        // one row: no y slope to fit (its sum of squares is 0), the x slope still goes
        HeightField row = HeightField.of(1, 5, new double[] {1, 2, 3, 4, 5}, 0.1);
        HeightField levelled = Levelling.PLANE.apply(row);
        for (int c = 0; c < 5; c++) {
            assertEquals(0, levelled.heightUm(0, c), 1e-15);
        }
    }
}
