package diffract.optics;

import diffract.colour.SpectralDensity;
import diffract.colour.Xyz;
import diffract.optics.patches.Direction;
import diffract.optics.illumination.Footprint;
import diffract.optics.illumination.GainFactor;
import diffract.optics.illumination.LightSource;
import diffract.optics.numerics.Covariance2;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.settings.GainModel;
import diffract.optics.settings.LightProfile;
import diffract.optics.settings.SpectralSettings;
import diffract.optics.settings.WavelengthSampling;
import diffract.optics.spectra.ExactSpectrum;
import diffract.optics.windows.CoherenceWindow;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import java.util.stream.IntStream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The filtered reference (pixel and light averages, exact wavelength integral) against brute force that knows
 * nothing of lobes: point evaluations of {@link ExactSpectrum} on a grid of sub-pixel directions, on a fine
 * wavelength grid, and on a grid of light directions, with the gain and shadowing at every sample; at the thesis'
 * 65 um coherence, on a blazed grating, the Elaphe-like patch and a rough random patch, 64 x 64 maps at
 * theta_i = 30 degrees.
 */
class FilteredReferenceTest {
    static final int SIZE = 64;
    static final CoherenceWindow WINDOW = CoherenceWindow.thesis();
    /**
     * Relative to a pixel's largest tristimulus value. Measured: 1.5e-4 at worst (the grating's brightest pixel), from
     * brute force's own midpoint sampling of the box (32 x 32) and of the light; the reference's stated tolerance is
     * 1e-4.
     */
    static final double TOLERANCE = 5e-4;

    static HeightField patch(String name) {
        switch (name) {
            case "blazed":
                return SyntheticPatches.blazed(2.5, 0.2, 20, 4, 16).meanSubtracted();
            case "elaphe-like":
                return SyntheticPatches.elapheLike().meanSubtracted();
            default:
                return NaiveDft.randomPatch(32, 32, 0.3, 0.25, 11);
        }
    }

    /** The light's azimuth in the plane of the patch's period (the gratings' x, the snake ridges' y). */
    static double phiOf(String name) {
        return name.equals("elaphe-like") ? 90 : 0;
    }

    static FilteredReference reference(HeightField patch) {
        return new FilteredReference(new ExactSpectrum(patch, WINDOW), WINDOW, new SpectralSettings(380, 780, 5), 1.5, GainModel.STAM);
    }

    @ParameterizedTest
    @ValueSource(strings = {"blazed", "elaphe-like", "rough"})
    void mapPixelsEqualBruteForceSupersampling(String name) {
        HeightField patch = patch(name);
        FilteredReference reference = reference(patch);
        ExactSpectrum exact = new ExactSpectrum(patch, WINDOW);
        Direction wi = Direction.fromSphericalDeg(30, phiOf(name));
        for (int[] pixel : brightestOnTheLineOfOrders(reference, wi, phiOf(name), 3)) {
            Xyz filtered = reference.mapPixel(wi, Covariance2.ZERO, pixel[0], pixel[1], SIZE);
            double[] brute = bruteForcePixel(exact, wi, pixel[0], pixel[1], 32, 0.25);
            assertClose(brute, filtered, name + " pixel " + pixel[0] + "," + pixel[1]);
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"blazed", "elaphe-like"})
    void aTwoDegreeLightEqualsBruteForceOverItsDirections(String name) {
        HeightField patch = patch(name);
        FilteredReference reference = reference(patch);
        ExactSpectrum exact = new ExactSpectrum(patch, WINDOW);
        Direction wi = Direction.fromSphericalDeg(30, phiOf(name));
        Covariance2 light = new LightSource(2.0, LightProfile.GAUSSIAN).uvCovariance(wi);
        int[] pixel = brightestOnTheLineOfOrders(reference, wi, phiOf(name), 1).get(0);
        Direction wr = Direction.fromProjected(BrdfMap.xOf(pixel[0], SIZE), BrdfMap.yOf(pixel[1], SIZE));
        double[] filtered = reference.at(wi, wr, new Footprint(0, 0, light));
        double[] brute = bruteForceLight(exact, wi, wr, light, 0.25);
        assertClose(brute, new Xyz(filtered[0], filtered[1], filtered[2]), name + " with a 2 degree light");
    }

    /**
     * A pixel with a light whose (u, v) covariance is not axis-aligned (azimuth 30 degrees): the reference splits it
     * into a diagonal part and a rank-one part; here the box is instead sampled at 32 x 32 directions, each with the
     * light's full Gaussian (the point path, which needs no split).
     */
    @Test
    void aTiltedLightOverAPixelEqualsSampledPixelOfTheLightAverage() {
        HeightField patch = patch("blazed");
        FilteredReference reference = reference(patch);
        Direction wi = Direction.fromSphericalDeg(30, 30);
        Covariance2 light = new LightSource(2.0, LightProfile.GAUSSIAN).uvCovariance(wi);
        assertTrue(Math.abs(light.xy()) > 0.1 * light.xx());
        // the first order at 550 nm, lambda / d = 0.22 along x from the mirror direction
        int column = (int) Math.floor((-wi.x() + 0.22 + 1) * SIZE / 2);
        int row = (int) Math.floor((1 + wi.y()) * SIZE / 2);
        Xyz filtered = reference.mapPixel(wi, light, column, row, SIZE);
        int n = 32;
        double half = 1.0 / SIZE;
        double[] sampled = new double[3];
        for (int a = 0; a < n; a++) {
            for (int b = 0; b < n; b++) {
                double x = BrdfMap.xOf(column, SIZE) - half + (2 * a + 1) * half / n;
                double y = BrdfMap.yOf(row, SIZE) - half + (2 * b + 1) * half / n;
                double[] v = reference.at(wi, Direction.fromProjected(x, y), new Footprint(0, 0, light));
                for (int i = 0; i < 3; i++) {
                    sampled[i] += v[i] / (n * n);
                }
            }
        }
        assertTrue(filtered.y() > 1e-4, "a lit pixel: " + filtered);
        assertClose(sampled, filtered, "tilted light over pixel " + column + "," + row);
    }

    /**
     * With no footprint it is the point reference integrated exactly in wavelength (0.05 nm steps here), to the
     * reference's stated tolerance, 1e-4 of the pixel's largest value (measured: 4e-5; each lobe's wavelength
     * integral is held to 1e-4 of itself).
     */
    @ParameterizedTest
    @ValueSource(strings = {"blazed", "rough"})
    void aPointEqualsThePointReferenceOnAFineWavelengthGrid(String name) {
        HeightField patch = patch(name);
        ExactSpectrum exact = new ExactSpectrum(patch, WINDOW);
        FilteredReference reference = reference(patch);
        DiffractionBrdf fine = new DiffractionBrdf(exact, WavelengthSampling.uniform(380, 780, 0.05), 1.5,
                GainModel.STAM);
        Direction wi = Direction.fromSphericalDeg(30, phiOf(name));
        for (double x : new double[] {-0.72, -0.51, -0.28, 0.1, 0.6}) {
            Direction wr = Direction.fromProjected(x, 0.0);
            double[] filtered = reference.at(wi, wr, Footprint.POINT);
            Xyz point = fine.xyz(wi, wr);
            double scale = Math.max(point.x(), Math.max(point.y(), point.z())) + 1e-15;
            assertEquals(point.x(), filtered[0], 1e-4 * scale, name + " x = " + x);
            assertEquals(point.y(), filtered[1], 1e-4 * scale, name + " x = " + x);
            assertEquals(point.z(), filtered[2], 1e-4 * scale, name + " x = " + x);
        }
    }

    /**
     * The reference of a 64 px map equals its own 512 px map averaged over 8 x 8 blocks (box averages add up), on a
     * 3 x 3 block of pixels across the first order of the grating.
     */
    @Test
    void aCoarsePixelIsTheAverageOfItsFinePixels() {
        HeightField patch = patch("blazed");
        FilteredReference reference = reference(patch);
        Direction wi = Direction.fromSphericalDeg(30, 0);
        int column = (int) Math.floor((-wi.x() + 0.22 + 1) * SIZE / 2);
        for (int i = column - 1; i <= column + 1; i++) {
            for (int j = SIZE / 2 - 1; j <= SIZE / 2; j++) {
                Xyz coarse = reference.mapPixel(wi, Covariance2.ZERO, i, j, SIZE);
                double[] fine = new double[3];
                int ii = i;
                int jj = j;
                double[][] parts = IntStream.range(0, 64).parallel().mapToObj(k -> {
                    Xyz c = reference.mapPixel(wi, Covariance2.ZERO, 8 * ii + k % 8, 8 * jj + k / 8, 8 * SIZE);
                    return new double[] {c.x(), c.y(), c.z()};
                }).toArray(double[][]::new);
                for (double[] p : parts) {
                    for (int k = 0; k < 3; k++) {
                        fine[k] += p[k] / 64;
                    }
                }
                assertClose(fine, coarse, "pixel " + i + "," + j);
            }
        }
    }

    static void assertClose(double[] expected, Xyz actual, String where) {
        double scale = Math.max(expected[0], Math.max(expected[1], expected[2]));
        String message = String.format("%s: expected (%.6e, %.6e, %.6e), got %s", where, expected[0], expected[1],
                expected[2], actual);
        assertTrue(scale > 0, message);
        assertEquals(expected[0], actual.x(), TOLERANCE * scale, message);
        assertEquals(expected[1], actual.y(), TOLERANCE * scale, message);
        assertEquals(expected[2], actual.z(), TOLERANCE * scale, message);
    }

    /**
     * The {@code count} brightest pixels of the map's line through the mirror direction along the light's azimuth
     * (where the orders lie), each at least 10 pixels from the next.
     */
    static java.util.List<int[]> brightestOnTheLineOfOrders(FilteredReference reference, Direction wi, double phiDeg,
                                                             int count) {
        boolean alongX = phiDeg == 0;
        int fixed = alongX ? (int) Math.floor((1 + wi.y()) * SIZE / 2) : (int) Math.floor((-wi.x() + 1) * SIZE / 2);
        double[] y = new double[SIZE];
        IntStream.range(0, SIZE).parallel().forEach(k -> y[k] = alongX
                ? reference.mapPixel(wi, Covariance2.ZERO, k, fixed, SIZE).y()
                : reference.mapPixel(wi, Covariance2.ZERO, fixed, k, SIZE).y());
        java.util.List<int[]> chosen = new java.util.ArrayList<>();
        boolean[] taken = new boolean[SIZE];
        for (int n = 0; n < count; n++) {
            int best = -1;
            for (int k = 0; k < SIZE; k++) {
                if (!taken[k] && (best < 0 || y[k] > y[best])) {
                    best = k;
                }
            }
            for (int k = Math.max(0, best - 10); k <= Math.min(SIZE - 1, best + 10); k++) {
                taken[k] = true;
            }
            chosen.add(alongX ? new int[] {best, fixed} : new int[] {fixed, best});
        }
        return chosen;
    }

    /** The pixel's box sampled at n x n directions, each integrated over wavelength by the trapezoid rule. */
    static double[] bruteForcePixel(ExactSpectrum exact, Direction wi, int column, int row, int n, double stepNm) {
        SpectralDensity density = new SpectralDensity(380, 780);
        double half = 1.0 / SIZE;
        double[][] rows = IntStream.range(0, n).parallel().mapToObj(b -> {
            double[] sum = new double[3];
            double[] f = new double[3];
            for (int a = 0; a < n; a++) {
                double x = BrdfMap.xOf(column, SIZE) - half + (2 * a + 1) * half / n;
                double y = BrdfMap.yOf(row, SIZE) - half + (2 * b + 1) * half / n;
                if (x * x + y * y >= 1) {
                    continue;
                }
                Direction wr = Direction.fromProjected(x, y);
                double gain = GainFactor.gainTimesShadowing(wi, wr, 1.5, GainModel.STAM);
                spectralSum(exact, density, -wi.x() - x, -wi.y() - y, -wi.z() - wr.z(), stepNm, gain / (n * n), f, sum);
            }
            return sum;
        }).toArray(double[][]::new);
        return total(rows);
    }

    /** The light's Gaussian in (u, v) sampled on a grid of shifts over +-5 standard deviations. */
    static double[] bruteForceLight(ExactSpectrum exact, Direction wi, Direction wr, Covariance2 light, double stepNm) {
        SpectralDensity density = new SpectralDensity(380, 780);
        double gain = GainFactor.gainTimesShadowing(wi, wr, 1.5, GainModel.STAM);
        double sx = Math.sqrt(light.xx());
        double sy = Math.sqrt(light.yy());
        int n = 48;
        double hx = 10 * sx / n;
        double hy = 10 * sy / n;
        double det = light.determinant();
        double[][] rows = IntStream.range(0, n + 1).parallel().mapToObj(b -> {
            double[] sum = new double[3];
            double[] f = new double[3];
            double dv = -5 * sy + b * hy;
            for (int a = 0; a <= n; a++) {
                double du = -5 * sx + a * hx;
                double q = (light.yy() * du * du - 2 * light.xy() * du * dv + light.xx() * dv * dv) / det;
                double weight = Math.exp(-0.5 * q) / (2 * Math.PI * Math.sqrt(det)) * hx * hy;
                spectralSum(exact, density, -wi.x() - wr.x() + du, -wi.y() - wr.y() + dv, -wi.z() - wr.z(), stepNm,
                        gain * weight, f, sum);
            }
            return sum;
        }).toArray(double[][]::new);
        return total(rows);
    }

    /** sum += scale * trapezoid over [380, 780] nm of f(lambda) |P(u, v, w, lambda)|^2. */
    private static void spectralSum(ExactSpectrum exact, SpectralDensity density, double u, double v, double w,
                                    double stepNm, double scale, double[] f, double[] sum) {
        int steps = (int) Math.round(400 / stepNm);
        for (int j = 0; j <= steps; j++) {
            double lambda = 380 + j * stepNm;
            double weight = (j == 0 || j == steps ? 0.5 : 1) * stepNm * scale;
            double p = exact.power(u, v, w, lambda * 1e-3);
            if (p == 0) {
                continue;
            }
            density.at(lambda, f);
            for (int k = 0; k < 3; k++) {
                sum[k] += weight * p * f[k];
            }
        }
    }

    private static double[] total(double[][] parts) {
        double[] t = new double[3];
        for (double[] p : parts) {
            for (int k = 0; k < 3; k++) {
                t[k] += p[k];
            }
        }
        return t;
    }
}
