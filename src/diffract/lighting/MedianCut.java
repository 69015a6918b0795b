package diffract.lighting;

import java.util.ArrayList;
import java.util.List;

/**
 * Median-cut light sampling (P. Debevec, "A Median Cut Algorithm for Light Probe Sampling", SIGGRAPH 2005 poster):
 * the map is split into 2^n regions of equal light energy and each region becomes one light at its energy
 * centroid carrying the region's total light.
 *
 * <p>Energy is luminance times solid angle (so the poles, whose pixels are small, weigh less). Each round splits
 * every region across its longer side, measured on the sphere (a region's width counts sin theta at its middle
 * row), at the row or column that halves its energy. A region's light points to its energy-weighted mean pixel,
 * carries the region's summed RGB radiance x solid angle and remembers the region's solid angle, so the lights
 * together carry exactly the map's total power ({@link LatLongMap#totalPower}).
 */
public final class MedianCut {
    private MedianCut() {
    }

    /** 2^{@code rounds} lights from the map, brightest first. */
    public static List<ExtendedLight> lights(LatLongMap map, int rounds) {
        if (rounds < 0 || rounds > 8) {
            throw new IllegalArgumentException("median-cut rounds must be in [0, 8], got " + rounds);
        }
        int w = map.width();
        int h = map.height();
        double[] energy = new double[w * h];
        for (int r = 0; r < h; r++) {
            double omega = map.solidAngle(r);
            for (int c = 0; c < w; c++) {
                energy[r * w + c] = omega * (0.2126 * map.get(c, r, 0) + 0.7152 * map.get(c, r, 1)
                        + 0.0722 * map.get(c, r, 2));
            }
        }
        List<int[]> regions = new ArrayList<>();
        regions.add(new int[] {0, 0, w, h}); // c0, r0, c1, r1 (exclusive)
        for (int round = 0; round < rounds; round++) {
            List<int[]> next = new ArrayList<>();
            for (int[] region : regions) {
                split(region, energy, w, h, next);
            }
            regions = next;
        }
        List<ExtendedLight> lights = new ArrayList<>();
        for (int[] region : regions) {
            lights.add(light(map, energy, region));
        }
        lights.sort((a, b) -> Double.compare(b.luminance(), a.luminance()));
        return lights;
    }

    private static void split(int[] region, double[] energy, int w, int h, List<int[]> out) {
        int c0 = region[0];
        int r0 = region[1];
        int c1 = region[2];
        int r1 = region[3];
        double middleTheta = Math.PI * (r0 + r1) / 2.0 / h;
        double widthOnSphere = (c1 - c0) * (2 * Math.PI / w) * Math.sin(middleTheta);
        double heightOnSphere = (r1 - r0) * (Math.PI / h);
        boolean acrossColumns = widthOnSphere >= heightOnSphere;
        int cells = acrossColumns ? c1 - c0 : r1 - r0;
        if (cells < 2) {
            acrossColumns = !acrossColumns;
            cells = acrossColumns ? c1 - c0 : r1 - r0;
            if (cells < 2) { // a single pixel cannot be split: it stays one region and an empty one joins it
                out.add(region);
                out.add(new int[] {c0, r0, c0, r0});
                return;
            }
        }
        double[] line = new double[cells];
        double total = 0;
        for (int r = r0; r < r1; r++) {
            for (int c = c0; c < c1; c++) {
                double e = energy[r * w + c];
                line[acrossColumns ? c - c0 : r - r0] += e;
                total += e;
            }
        }
        int cut = 1;
        double sum = line[0];
        // the cut after which the first part holds (as nearly as whole pixels allow) half the energy
        while (cut < cells - 1 && sum + line[cut] / 2 < total / 2) {
            sum += line[cut];
            cut++;
        }
        if (acrossColumns) {
            out.add(new int[] {c0, r0, c0 + cut, r1});
            out.add(new int[] {c0 + cut, r0, c1, r1});
        } else {
            out.add(new int[] {c0, r0, c1, r0 + cut});
            out.add(new int[] {c0, r0 + cut, c1, r1});
        }
    }

    private static ExtendedLight light(LatLongMap map, double[] energy, int[] region) {
        int w = map.width();
        double[] rgb = new double[3];
        double[] centroid = new double[3];
        double solidAngle = 0;
        double weight = 0;
        for (int r = region[1]; r < region[3]; r++) {
            double omega = map.solidAngle(r);
            for (int c = region[0]; c < region[2]; c++) {
                for (int k = 0; k < 3; k++) {
                    rgb[k] += map.get(c, r, k) * omega;
                }
                double e = energy[r * w + c];
                double[] d = map.pixelDirection(c, r);
                for (int k = 0; k < 3; k++) {
                    centroid[k] += e * d[k];
                }
                weight += e;
                solidAngle += omega;
            }
        }
        double length = Math.sqrt(centroid[0] * centroid[0] + centroid[1] * centroid[1] + centroid[2] * centroid[2]);
        double[] direction;
        if (weight > 0 && length > 1e-12 * weight) {
            direction = new double[] {centroid[0] / length, centroid[1] / length, centroid[2] / length};
        } else { // a dark region: its geometric middle
            direction = map.direction((region[0] + region[2]) / 2.0, (region[1] + region[3]) / 2.0);
        }
        return ExtendedLight.of(direction, rgb, solidAngle);
    }
}
