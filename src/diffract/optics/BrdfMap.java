package diffract.optics;

import diffract.colour.Xyz;
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
        float[] out = new float[size * size * 3];
        forEachRow(size, reporter, "BRDF map " + size + "x" + size, j -> {
            for (int i = 0; i < size; i++) {
                Xyz c = brdf.mapPixel(wi, i, j, size);
                int p = 3 * (j * size + i);
                out[p] = (float) c.x();
                out[p + 1] = (float) c.y();
                out[p + 2] = (float) c.z();
            }
        });
        return out;
    }

    /** The monochromatic relative BRDF per pixel, 1 float per pixel. */
    public static float[] monochromatic(DiffractionBrdf brdf, Direction wi, double lambdaNm, int size, Reporter reporter) {
        float[] out = new float[size * size];
        forEachRow(size, reporter, "BRDF map " + size + "x" + size + " at " + lambdaNm + " nm", j -> {
            for (int i = 0; i < size; i++) {
                double x = xOf(i, size);
                double y = yOf(j, size);
                if (x * x + y * y >= 1.0) {
                    continue;
                }
                out[j * size + i] = (float) brdf.relative(wi, Direction.fromProjected(x, y), lambdaNm);
            }
        });
        return out;
    }

    private static void forEachRow(int size, Reporter reporter, String task, java.util.function.IntConsumer row) {
        if (size < 1) {
            throw new IllegalArgumentException("map size must be >= 1, got " + size);
        }
        AtomicInteger done = new AtomicInteger();
        IntStream.range(0, size).parallel().forEach(j -> {
            row.accept(j);
            reporter.progress(task, done.incrementAndGet() / (double) size);
        });
    }
}
