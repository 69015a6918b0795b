package diffract.jrtr.textures;

import com.jogamp.opengl.GL3;
import diffract.jrtr.gl.PixelRect;

import java.util.Arrays;

/**
 * The tiles of one frame drawn in parts (into a {@link FloatFramebuffer}), each sized to take about a target time, so a render
 * loop can look at its input between tiles however expensive the frame (on a software rasteriser a full frame of
 * a costly shader takes seconds to minutes, and a GL call cannot be interrupted). Tiles go in rows from the top,
 * left to right: whole rows while a row costs less than the target, else parts of one pixel row.
 *
 * <p>A pixel costs far more where the picture shows an expensive surface than where it shows the background, so a
 * tile sized by the rows above it can take many times the target. Tiles are therefore sized by a {@link Cost}
 * profile, a fixed cost per draw (vertex work, setup) plus a cost per pixel for each row, measured on a frame of
 * the same kind drawn before (the same picture at another resolution, or a recent one), scaled by how this
 * frame's tiles compare with it. Without a profile, tiles start at {@value #FIRST_TILE_PX} pixels, are sized for
 * the most expensive pixels seen lately (a level that decays by {@value #CEILING_DECAY} per tile, so one tile
 * slowed by another process does not shrink all later ones) and grow at most {@value #MAX_GROWTH} times per tile.
 * Where the fixed cost exceeds half the target, tiles take twice the fixed cost, so the frame still progresses.
 */
public final class TiledFrame {
    /** The first tile of a frame without a cost profile, in pixels. */
    public static final int FIRST_TILE_PX = 16;
    /** Without a profile, a tile is at most this many times the previous one. */
    static final int MAX_GROWTH = 4;
    /** Without a profile, the cost per pixel that sizes tiles falls to this share of itself per tile. */
    static final double CEILING_DECAY = 0.8;
    /** How much cheaper than its profile a frame is trusted to be. */
    static final double LOWEST_SCALE = 1.0 / 64;
    /** Tiles whose comparison with the profile sets its scale. */
    static final int RECENT_TILES = 4;
    /** A tile whose pixels took at least this share of the target compares the frame with its profile. */
    static final double TELLING_SHARE = 0.25;

    /**
     * What drawing a frame of some kind costs: {@code fixedMs} per draw plus, per pixel, the cost of its row.
     *
     * @param fixedMs       milliseconds per draw whatever its size (0 or more)
     * @param rowMsPerPixel milliseconds per pixel of each row, top down, of the frame it was measured on
     */
    public record Cost(double fixedMs, double[] rowMsPerPixel) {
        /** The highest cost per pixel between {@code top} and {@code bottom}, fractions of the height from the top. */
        double msPerPixel(double top, double bottom) {
            int n = rowMsPerPixel.length;
            int first = Math.min(n - 1, (int) Math.floor(top * n));
            int last = Math.max(first, Math.min(n - 1, (int) Math.ceil(bottom * n) - 1));
            double highest = 0;
            for (int i = first; i <= last; i++) {
                highest = Math.max(highest, rowMsPerPixel[i]);
            }
            return highest;
        }

        /** This cost with every pixel {@code factor} times as expensive. */
        public Cost scaledBy(double factor) {
            double[] rows = rowMsPerPixel.clone();
            for (int i = 0; i < rows.length; i++) {
                rows[i] *= factor;
            }
            return new Cost(fixedMs, rows);
        }

        /** The mean cost per pixel. */
        public double meanMsPerPixel() {
            double sum = 0;
            for (double rate : rowMsPerPixel) {
                sum += rate;
            }
            return sum / rowMsPerPixel.length;
        }

        /** Milliseconds for a {@code width} x {@code height} frame drawn in tiles of about {@code tileMs}. */
        public double frameMs(int width, int height, double tileMs) {
            double pixelMs = meanMsPerPixel() * width * height;
            double tiles = Math.ceil(pixelMs / Math.max(tileMs - fixedMs, fixedMs));
            return pixelMs + Math.max(1, tiles) * fixedMs;
        }
    }

    private final int width;
    private final int height;
    private final double tileMs;
    private final Cost profile;
    /** The cost per pixel of each row as measured here (0 where not drawn yet). */
    private final double[] rowMsPerPixel;
    private final double[] recentScales = new double[RECENT_TILES];
    private long tilePixels = FIRST_TILE_PX;
    private double fixedMs = Double.POSITIVE_INFINITY;
    private double ceilingMsPerPixel;
    private int rowsDone;
    private int rowHeight;
    private int x;
    private int tiles;
    private double drawnMs;

    /**
     * @param width   the frame's width in pixels
     * @param height  the frame's height in pixels
     * @param tileMs  the time a tile should take
     * @param profile the cost of a frame of the same kind drawn before ({@link #cost()}), or null
     */
    public TiledFrame(int width, int height, double tileMs, Cost profile) {
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("frame of " + width + "x" + height);
        }
        this.width = width;
        this.height = height;
        this.tileMs = tileMs;
        this.profile = profile;
        this.rowMsPerPixel = new double[height];
        Arrays.fill(recentScales, 1);
        if (profile != null) {
            fixedMs = profile.fixedMs();
        }
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    public boolean isComplete() {
        return rowsDone >= height();
    }

    /** The share of the frame's pixels drawn, 0..1. */
    public double fractionDone() {
        return ((double) rowsDone * width() + (double) x * rowHeight) / ((double) width() * height());
    }

    public int tilesDrawn() {
        return tiles;
    }

    /** The time the tiles drawn so far took, in milliseconds. */
    public double drawnMs() {
        return drawnMs;
    }

    /**
     * What this frame cost per row, as far as drawn (rows not drawn yet take the profile's cost, or the highest
     * measured): the profile of the next frame of its kind.
     */
    public Cost cost() {
        double highest = 0;
        for (double rate : rowMsPerPixel) {
            highest = Math.max(highest, rate);
        }
        double[] rows = new double[rowMsPerPixel.length];
        for (int i = 0; i < rows.length; i++) {
            rows[i] = i < rowsDone ? rowMsPerPixel[i] : profile != null ? predictedMsPerPixel(i, i + 1) : highest;
        }
        return new Cost(Double.isInfinite(fixedMs) ? 0 : fixedMs, rows);
    }

    /** The next tile to draw; null when the frame is complete. */
    public PixelRect nextTile() {
        if (isComplete()) {
            return null;
        }
        double budget = Math.max(tileMs, 2 * (Double.isInfinite(fixedMs) ? 0 : fixedMs))
                - (Double.isInfinite(fixedMs) ? 0 : fixedMs);
        if (x == 0) {
            rowHeight = rowsFitting(budget);
        }
        int tileWidth = rowHeight > 1 ? width() : (int) Math.max(1, Math.min(width() - x, pixelsFitting(budget)));
        return new PixelRect(x, height() - rowsDone - rowHeight, tileWidth, rowHeight);
    }

    /** Whole rows from {@link #rowsDone} whose pixels take at most {@code budget} ms; at least one. */
    private int rowsFitting(double budget) {
        int rowsLeft = height() - rowsDone;
        if (profile == null) {
            return (int) Math.max(1, Math.min(rowsLeft, tilePixels / width()));
        }
        double ms = 0;
        int rows = 0;
        while (rows < rowsLeft) {
            ms += width() * predictedMsPerPixel(rowsDone + rows, rowsDone + rows + 1);
            if (ms > budget) {
                break;
            }
            rows++;
        }
        return Math.max(1, rows);
    }

    /** Pixels of the current row that take at most {@code budget} ms. */
    private long pixelsFitting(double budget) {
        if (profile == null) {
            return tilePixels;
        }
        return (long) Math.max(1, Math.min(width(), budget / predictedMsPerPixel(rowsDone, rowsDone + 1)));
    }

    /** The profile's cost per pixel of rows {@code from..to} of this frame, scaled as this frame's tiles compare. */
    private double predictedMsPerPixel(int from, int to) {
        return Math.max(1e-9, scale() * profile.msPerPixel((double) from / height(), (double) to / height()));
    }

    /** How this frame's pixels compare with the profile's: the highest ratio of the recent telling tiles. */
    private double scale() {
        double scale = LOWEST_SCALE;
        for (double s : recentScales) {
            scale = Math.max(scale, s);
        }
        return scale;
    }

    /** Records that {@code tile} (the last {@link #nextTile}) was drawn in {@code ms}, and sizes the next one. */
    public void tileDrawn(PixelRect tile, double ms) {
        int top = height() - tile.y() - tile.height();
        double predicted = profile == null ? 0 : tile.area() * predictedMsPerPixel(top, top + tile.height());
        fixedMs = Math.min(fixedMs, ms);
        // the fixed cost is the quickest tile's time, but at most half of this one's: the rest is its pixels'
        double pixelMs = ms - Math.min(fixedMs, ms / 2);
        double perPixel = pixelMs / tile.area();
        for (int row = top; row < top + tile.height(); row++) {
            rowMsPerPixel[row] = Math.max(rowMsPerPixel[row], perPixel);
        }
        if (profile != null && predicted > 0 && pixelMs >= TELLING_SHARE * tileMs) {
            // how this frame's pixels compare with the profile's, measured where a tile did real work (the times
            // of quick tiles are mostly noise, and a profile's cheap rows are its least reliable)
            double ratio = pixelMs / predicted * scale();
            System.arraycopy(recentScales, 1, recentScales, 0, RECENT_TILES - 1);
            recentScales[RECENT_TILES - 1] = ratio;
        }
        ceilingMsPerPixel = Math.max(perPixel, ceilingMsPerPixel * CEILING_DECAY);
        double budget = Math.max(tileMs, 2 * fixedMs) - fixedMs;
        tilePixels = Math.max(1, Math.min(tilePixels * MAX_GROWTH, (long) Math.min(Integer.MAX_VALUE,
                budget / Math.max(ceilingMsPerPixel, 1e-9))));
        tiles++;
        drawnMs += ms;
        x += tile.width();
        if (x >= width()) {
            x = 0;
            rowsDone += rowHeight;
        }
    }

    /**
     * Copies the part drawn so far from {@code framebuffer} (this frame's size) onto a {@code toWidth} x
     * {@code toHeight} framebuffer {@code target}, scaled as the whole frame would be (the full rows, then the tiles
     * of the row under way).
     */
    public void blitDrawnPart(GL3 gl, FloatFramebuffer framebuffer, int target, int toWidth, int toHeight) {
        PixelRect rows = new PixelRect(0, height() - rowsDone, width(), rowsDone);
        framebuffer.blitTo(gl, rows, target, rows.scaled(width(), height(), toWidth, toHeight));
        if (x > 0) {
            PixelRect row = new PixelRect(0, height() - rowsDone - rowHeight, x, rowHeight);
            framebuffer.blitTo(gl, row, target, row.scaled(width(), height(), toWidth, toHeight));
        }
    }
}
