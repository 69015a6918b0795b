package diffract.optics.maps;

import diffract.colour.DeltaEStatistics;
import diffract.optics.BrdfMap;

import java.util.List;
import java.util.Locale;

/**
 * How far one colour BRDF map is from another, as people see them: both maps' XYZ are multiplied by the same
 * display exposure, then compared pixel by pixel in CIEDE2000 (L*a*b* with the D65 white) inside the map's unit
 * disk, and once more over the lit pixels only (exposed Y above 1 % of white in either map), because most of a
 * BRDF map is black in both and dilutes the mean.
 *
 * @param lit null when no pixel is lit
 */
public record BrdfMapDifference(double exposure, DeltaEStatistics disk, DeltaEStatistics lit) {
    /** A pixel counts as lit when its exposed Y exceeds 1 % of white (L* above 9). */
    public static final double LIT_Y = 0.01;

    /** @param xyzA,xyzB S x S maps, 3 floats (X, Y, Z) per pixel, rows from the top ({@link BrdfMap}'s layout) */
    public static BrdfMapDifference of(float[] xyzA, float[] xyzB, int size, double exposure) {
        if (xyzA.length != 3 * size * size || xyzB.length != xyzA.length) {
            throw new IllegalArgumentException("maps of " + xyzA.length + " and " + xyzB.length
                    + " floats are not both " + size + "x" + size + " XYZ");
        }
        Exposed e = Exposed.of(List.of(xyzA), List.of(xyzB), List.of(exposure), size);
        return new BrdfMapDifference(exposure, DeltaEStatistics.of(e.a(), e.b(), e.disk()),
                e.litCount() > 0 ? DeltaEStatistics.of(e.a(), e.b(), e.lit()) : null);
    }

    /**
     * Pairs of S x S maps side by side, each pair times its display exposure, with the masks both statistics run
     * over: inside the unit disk, and lit (exposed Y above {@link #LIT_Y} in either map).
     */
    public record Exposed(float[] a, float[] b, boolean[] disk, boolean[] lit, int litCount) {
        public static Exposed of(List<float[]> mapsA, List<float[]> mapsB, List<Double> exposures, int size) {
            int pairs = mapsA.size();
            if (mapsB.size() != pairs || exposures.size() != pairs) {
                throw new IllegalArgumentException("need one map B and one exposure per map A");
            }
            int pixels = size * size;
            float[] a = new float[3 * pixels * pairs];
            float[] b = new float[a.length];
            boolean[] disk = new boolean[pixels * pairs];
            boolean[] lit = new boolean[disk.length];
            int litCount = 0;
            for (int l = 0; l < pairs; l++) {
                float[] mapA = mapsA.get(l);
                float[] mapB = mapsB.get(l);
                if (mapA.length != 3 * pixels || mapB.length != 3 * pixels) {
                    throw new IllegalArgumentException("maps must be " + size + "x" + size + " XYZ");
                }
                double exposure = exposures.get(l);
                for (int j = 0; j < size; j++) {
                    for (int i = 0; i < size; i++) {
                        int p = j * size + i;
                        int q = l * pixels + p;
                        double x = BrdfMap.xOf(i, size);
                        double y = BrdfMap.yOf(j, size);
                        disk[q] = x * x + y * y < 1;
                        for (int k = 0; k < 3; k++) {
                            a[3 * q + k] = (float) (mapA[3 * p + k] * exposure);
                            b[3 * q + k] = (float) (mapB[3 * p + k] * exposure);
                        }
                        lit[q] = disk[q] && Math.max(a[3 * q + 1], b[3 * q + 1]) > LIT_Y;
                        litCount += lit[q] ? 1 : 0;
                    }
                }
            }
            return new Exposed(a, b, disk, lit, litCount);
        }
    }

    public int litPixels() {
        return lit == null ? 0 : lit.pixels();
    }

    /** "CIEDE2000 mean M, p95 P, p99 Q, max X over N pixels; lit: ... over L pixels (exposure E)". */
    public String summary() {
        return String.format(Locale.ROOT, "CIEDE2000 %s over %d pixels; lit: %s over %d pixels (exposure %s)",
                format(disk), disk.pixels(), format(lit), litPixels(), exposure);
    }

    private static String format(DeltaEStatistics s) {
        if (s == null) {
            return "mean -, p95 -, p99 -, max -";
        }
        return String.format(Locale.ROOT, "mean %.3f, p95 %.3f, p99 %.3f, max %.2f", s.mean(), s.p95(), s.p99(), s.max());
    }
}
