package diffract.jrtr.textures;

import diffract.jrtr.gl.PixelRect;
import diffract.util.TestReport;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A frame drawn in tiles, with simulated draw times (no clock): every pixel drawn exactly once, rows from the top,
 * and tiles that stay near the target time where the picture's cost per pixel jumps a hundredfold from the
 * background to the surface.
 */
class TiledFrameTest {
    static final double TILE_MS = 100;
    static final double FIXED_MS = 1;

    /** Milliseconds per pixel at (x, y), fractions of the frame, y from the top. */
    interface PixelCost {
        double at(double x, double y);
    }

    /** A disc in the upper part of the picture costs 0.2 ms a pixel, the background 1/100 of that. */
    static final PixelCost SURFACE = (x, y) -> (x - 0.5) * (x - 0.5) * 1.78 + (y - 0.35) * (y - 0.35) < 0.06 ? 0.2
            : 0.002;
    /** The same picture drawn 30 times cheaper (a preview). */
    static final PixelCost PREVIEW = (x, y) -> SURFACE.at(x, y) / 30;

    record Drawn(TiledFrame.Cost cost, double worstMs, double totalMs, int tiles) {
    }

    /** Draws a frame tile by tile, the time of each tile being its fixed cost plus its pixels' costs. */
    static Drawn draw(int width, int height, PixelCost cost, TiledFrame.Cost profile) {
        TiledFrame frame = new TiledFrame(width, height, TILE_MS, profile);
        int[] drawn = new int[width * height];
        double worst = 0;
        double total = 0;
        int previousTop = -1;
        for (PixelRect tile = frame.nextTile(); tile != null; tile = frame.nextTile()) {
            int top = height - tile.y() - tile.height();
            assertTrue(top >= previousTop, "rows go from the top down");
            previousTop = top;
            double ms = FIXED_MS;
            for (int y = tile.y(); y < tile.y() + tile.height(); y++) {
                for (int x = tile.x(); x < tile.x() + tile.width(); x++) {
                    drawn[y * width + x]++;
                    ms += cost.at((x + 0.5) / width, 1 - (y + 0.5) / height);
                }
            }
            frame.tileDrawn(tile, ms);
            worst = Math.max(worst, ms);
            total += ms;
        }
        assertTrue(frame.isComplete());
        assertEquals(1.0, frame.fractionDone(), 1e-12);
        assertNull(frame.nextTile());
        for (int i = 0; i < drawn.length; i++) {
            assertEquals(1, drawn[i], "pixel " + i + " drawn " + drawn[i] + " times");
        }
        return new Drawn(frame.cost(), worst, total, frame.tilesDrawn());
    }

    @Test
    void everyPixelIsDrawnOnceWhateverTheSize() {
        for (int[] size : new int[][] {{1, 1}, {1, 37}, {37, 1}, {100, 75}, {333, 7}}) {
            draw(size[0], size[1], SURFACE, null);
            draw(size[0], size[1], (x, y) -> 500, null); // one pixel takes five targets: tiles of one pixel
        }
    }

    @Test
    void withoutAProfileTilesStartSmallAndGrowAtMostFourfold() {
        TiledFrame frame = new TiledFrame(800, 600, TILE_MS, null);
        PixelRect first = frame.nextTile();
        assertEquals(TiledFrame.FIRST_TILE_PX, first.area());
        frame.tileDrawn(first, 0.01); // very cheap: the next may grow, but only fourfold
        assertEquals(TiledFrame.MAX_GROWTH * TiledFrame.FIRST_TILE_PX, frame.nextTile().area());
    }

    @Test
    void theProfileOfTheCoarserPassKeepsEveryTileNearTheTarget() {
        // the refinement's ladder: 1/8 without a profile, then each pass sized by the one before
        Drawn eighth = draw(100, 75, SURFACE, null);
        Drawn quarter = draw(200, 150, SURFACE, eighth.cost());
        Drawn half = draw(400, 300, SURFACE, quarter.cost());
        Drawn full = draw(800, 600, SURFACE, half.cost());
        TestReport.printf(TiledFrameTest.class, "surface 100x cheaper in the background; worst tile / target:"
                        + " 1/8 %.2f (no profile), 1/4 %.2f, 1/2 %.2f, full %.2f; full frame %d tiles, %.0f ms%n",
                eighth.worstMs() / TILE_MS, quarter.worstMs() / TILE_MS, half.worstMs() / TILE_MS,
                full.worstMs() / TILE_MS, full.tiles(), full.totalMs());
        for (Drawn d : new Drawn[] {quarter, half, full}) {
            assertTrue(d.worstMs() < 3 * TILE_MS, "a tile took " + d.worstMs() + " ms");
        }
        // tiles near the target, not a crawl of tiny ones: the fixed costs stay a small share of the frame
        assertTrue(full.tiles() * FIXED_MS < 0.1 * full.totalMs(), full.tiles() + " tiles");
    }

    @Test
    void aPreviewProfileScaledUpSizesTheFirstPassOfExpensiveSettings() {
        Drawn preview = draw(100, 75, PREVIEW, null);
        // the configured settings' cost is unknown: assumed 64 times the preview's, 30 times in truth
        Drawn configured = draw(100, 75, SURFACE, preview.cost().scaledBy(64));
        assertTrue(configured.worstMs() < 3 * TILE_MS, "a tile took " + configured.worstMs() + " ms");
    }

    @Test
    void theCostEstimatesTheWholeFrame() {
        Drawn half = draw(400, 300, SURFACE, null);
        Drawn full = draw(800, 600, SURFACE, half.cost());
        double estimate = half.cost().frameMs(800, 600, TILE_MS);
        // the profile keeps each row's highest cost per pixel: an estimate on the safe side, within 2x here
        assertTrue(estimate >= 0.9 * full.totalMs() && estimate <= 2 * full.totalMs(),
                "estimate " + estimate + " ms, drawn in " + full.totalMs() + " ms");
    }

    @Test
    void aFixedCostAboveHalfTheTargetGivesTilesOfTwiceIt() {
        double[] rows = new double[300];
        java.util.Arrays.fill(rows, 0.01);
        // 10 ms per draw: the pixels get the other 90 ms of the target, 9000 pixels, 22 rows of 400
        assertEquals(22, new TiledFrame(400, 300, TILE_MS, new TiledFrame.Cost(10, rows)).nextTile().height());
        // 150 ms per draw: a tile takes 300 ms, half of it pixels, 15000 pixels, 37 rows: the frame progresses
        assertEquals(37, new TiledFrame(400, 300, TILE_MS, new TiledFrame.Cost(150, rows)).nextTile().height());
    }

    @Test
    void rectanglesScaleWithAdjacentEdges() {
        PixelRect left = new PixelRect(0, 0, 3, 5);
        PixelRect right = new PixelRect(3, 0, 4, 5);
        PixelRect l = left.scaled(7, 5, 800, 600);
        PixelRect r = right.scaled(7, 5, 800, 600);
        assertEquals(l.x() + l.width(), r.x(), "no gap, no overlap");
        assertEquals(800, r.x() + r.width());
        assertEquals(600, l.height());
    }
}
