package diffract.optics;

import diffract.colour.Xyz;
import diffract.optics.patches.Direction;
import diffract.optics.settings.PixelFilter;
import diffract.util.Reporter;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.IntStream;

/**
 * A BRDF map, the thesis' way of looking at a BRDF: pixel (i, j) of an S x S image (i column, j row,
 * from the top left) shows the viewing direction omega_r = (x, y, sqrt(1 - x^2 - y^2)) with
 * x = 2 (i + 0.5) / S - 1 and y = 1 - 2 (j + 0.5) / S, for a fixed light direction omega_i. Pixels whose centre
 * lies outside the unit disk are black (0). A pixel shows the BRDF at that direction, or, for the reference and the
 * lobes method with {@link PixelFilter#BOX}, its average over the pixel's square of side 2 / S
 * ({@link DiffractionBrdf#mapPixel}).
 */
public final class BrdfMap {
    private BrdfMap() {
    }

    /** The tangent-frame x of pixel column i. */
    public static double xOf(int column, int size) {
        return 2.0 * (column + 0.5) / size - 1.0;
    }

    /** The tangent-frame y of pixel row j. */
    public static double yOf(int row, int size) {
        return 1.0 - 2.0 * (row + 0.5) / size;
    }

    /** CIE XYZ per pixel, 3 floats per pixel, rows from the top. */
    public static float[] xyz(DiffractionBrdf brdf, Direction wi, int size, Reporter reporter) {
        return xyz(brdf, wi, size, new MapBand(0, size), reporter);
    }

    /**
     * Rows {@code band} of the S x S map: the same floats, bit for bit, as those rows of {@link #xyz(DiffractionBrdf,
     * Direction, int, Reporter)}, since every pixel is computed alone; 3 floats per pixel, the band's first row first.
     */
    public static float[] xyz(DiffractionBrdf brdf, Direction wi, int size, MapBand band, Reporter reporter) {
        float[] out = new float[size * band.rows() * 3];
        brdf.prepare(wi, reporter);
        forEachPixel(size, band, reporter, "BRDF map " + size + "x" + size + band.label(size), (i, j) -> {
            Xyz c = brdf.mapPixel(wi, i, j, size);
            int p = 3 * ((j - band.fromRow()) * size + i);
            out[p] = (float) c.x();
            out[p + 1] = (float) c.y();
            out[p + 2] = (float) c.z();
        });
        return out;
    }

    /** The monochromatic relative BRDF per pixel, 1 float per pixel. */
    public static float[] monochromatic(DiffractionBrdf brdf, Direction wi, double lambdaNm, int size, Reporter reporter) {
        return monochromatic(brdf, wi, lambdaNm, size, new MapBand(0, size), reporter);
    }

    /** Rows {@code band} of {@link #monochromatic(DiffractionBrdf, Direction, double, int, Reporter)}, bit for bit. */
    public static float[] monochromatic(DiffractionBrdf brdf, Direction wi, double lambdaNm, int size, MapBand band,
                                        Reporter reporter) {
        float[] out = new float[size * band.rows()];
        brdf.prepare(wi, reporter);
        forEachPixel(size, band, reporter, "BRDF map " + size + "x" + size + band.label(size) + " at " + lambdaNm
                + " nm", (i, j) -> {
            double x = xOf(i, size);
            double y = yOf(j, size);
            if (x * x + y * y < 1.0) {
                out[(j - band.fromRow()) * size + i] = (float) brdf.relative(wi, Direction.fromProjected(x, y), lambdaNm);
            }
        });
        return out;
    }

    /** Pixel (column, row) of the map. */
    private interface PixelTask {
        void run(int column, int row);
    }

    /**
     * Every pixel, handed out one at a time to as many workers as there are processors: pixels differ in cost by
     * orders of magnitude (the orders and the mirror against the dark), so a fixed split would leave workers idle.
     */
    private static void forEachPixel(int size, MapBand band, Reporter reporter, String task, PixelTask pixel) {
        if (size < 1) {
            throw new IllegalArgumentException("map size must be >= 1, got " + size);
        }
        if (band.toRow() > size) {
            throw new IllegalArgumentException("rows " + band + " lie outside a map of " + size + " rows");
        }
        int total = size * band.rows();
        int first = band.fromRow() * size;
        AtomicInteger next = new AtomicInteger();
        AtomicInteger done = new AtomicInteger();
        int workers = Math.max(1, Math.min(total, Runtime.getRuntime().availableProcessors()));
        IntStream.range(0, workers).parallel().forEach(w -> {
            for (int p = next.getAndIncrement(); p < total; p = next.getAndIncrement()) {
                pixel.run((first + p) % size, (first + p) / size);
                int finished = done.incrementAndGet();
                if (finished % size == 0 || finished == total) {
                    reporter.progress(task, finished / (double) total);
                }
            }
        });
    }
}
