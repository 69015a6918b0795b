package diffract.optics;

import diffract.colour.Xyz;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.settings.PixelFilter;
import diffract.optics.spectra.ExactSpectrum;
import diffract.optics.spectra.PatchSpectrum;
import diffract.optics.spectra.TaylorGaussianSpectrum;
import diffract.optics.spectra.TaylorSincSpectrum;
import diffract.optics.windows.CoherenceWindow;
import diffract.optics.windows.WindowPlacement;
import diffract.optics.windows.WindowRadii;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import java.util.Locale;
import java.util.function.Function;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The window averaged over its position ({@link WindowPlacement#AVERAGED}) against brute force: the thesis' fixed
 * window, evaluated on the scan cut at many places (cyclic shifts of the height field: moving the window by x0 over
 * the DFT's periodic patch is the same as moving the patch by -x0), averaged. With K x K shifts spaced L / K apart a
 * pair of texels m, m' keeps its phase exp(2 pi i (m - m') . x0 / L) only where m - m' is a multiple of K along both
 * axes; for K = 8 and sigma_f = 0.47 texels such pairs weigh exp(-8^2 / (4 sigma^2)) = 1e-31, so the brute force is the
 * average to rounding. Every method on the CPU: the exact spectrum, the filtered reference, FLSS, NMM, PQ and the
 * lobes method (whose fixed window keeps texel pairs at this width).
 *
 * <p>The scan is 48 um wide, as wide as three quarters of the 65 um coherence length: its window keeps pairs whose
 * weight is 0.3 (the nearest), so the fixed model differs from the average and depends on where the scan is cut,
 * which {@link #theFixedWindowDependsOnWhereTheScanIsCut} measures (a negative control: the brute force would pass
 * trivially if nothing moved).
 */
class AveragedWindowTest {
    /** 128 x 128 samples of 0.375 um: a 48 um scan, sigma_f = 0.47 texels at 65 um. */
    static final HeightField SCAN = wideScan(128, 0.375);
    static final int SHIFTS = 8;
    static final Direction LIGHT = Direction.fromSphericalDeg(30, 90);
    static final double LAMBDA_NM = 550;
    static final double RIDGE_UM = WideScan.RIDGE_UM;

    static HeightField wideScan(int samples, double pixelUm) {
        return WideScan.of(samples, pixelUm);
    }

    /** The scan cut (dx, dy) samples further on: the height field rolled cyclically. */
    static HeightField shifted(HeightField field, int dx, int dy) {
        int rows = field.rows();
        int cols = field.cols();
        double[] h = new double[rows * cols];
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                h[r * cols + c] = field.heightUm(Math.floorMod(r + dy, rows), Math.floorMod(c + dx, cols));
            }
        }
        return HeightField.of(rows, cols, h, field.pixelSizeXUm(), field.pixelSizeYUm());
    }

    /** Lookups around the first order of the ridge (v = lambda / period) and the mirror, at 550 nm. */
    static double[][] lookups() {
        double[][] uv = new double[2 * 9 * 5][];
        int k = 0;
        for (double centreV : new double[] {0.0, LAMBDA_NM * 1e-3 / RIDGE_UM}) {
            for (int i = -4; i <= 4; i++) {
                for (int j = -2; j <= 2; j++) {
                    uv[k++] = new double[] {0.0021 * j, centreV + 0.0017 * i};
                }
            }
        }
        return uv;
    }

    /**
     * The agreement to expect, of the peak: rounding for the exact spectrum; the Taylor methods read float32 terms,
     * which each cut of the scan rounds differently (1e-7 of the peak).
     */
    static double tolerance(Method method) {
        return method == Method.EXACT ? 1e-12 : 1e-6;
    }

    /** The CPU methods whose fixed window the brute force averages. */
    enum Method {
        EXACT, FLSS, NMM, PQ, LOBES
    }

    /** |P|^2 at {@link #lookups} of the method built on {@code field} with its window placed as {@code placement}. */
    static double[] powers(Method method, HeightField field, WindowPlacement placement) {
        if (method == Method.NMM) {
            return nmmLuminance(field, placement);
        }
        CoherenceWindow window = CoherenceWindow.thesis().placed(placement);
        PatchSpectrum spectrum = switch (method) {
            case EXACT -> new ExactSpectrum(field, window);
            case FLSS -> new TaylorGaussianSpectrum(TaylorTermComputer.compute(field, 14, Reporter.SILENT), 14,
                    new WindowRadii(3, 3), 0.0, window);
            case PQ -> new TaylorSincSpectrum(TaylorTermComputer.compute(field, 14, Reporter.SILENT), 14,
                    new WindowRadii(2, 2), 0.0, 3, 3, placement);
            case LOBES -> lobes(field, placement);
            case NMM -> throw new IllegalStateException("NMM integrates its own wavelengths");
        };
        double w = -(LIGHT.z() + 0.95);
        double[][] uv = lookups();
        double[] out = new double[uv.length];
        for (int i = 0; i < uv.length; i++) {
            out[i] = spectrum.power(uv[i][0], uv[i][1], w, LAMBDA_NM * 1e-3);
        }
        return out;
    }

    /** NMM's Y (its own wavelengths, FLSS's spectrum) towards the directions of the lookups. */
    private static double[] nmmLuminance(HeightField field, WindowPlacement placement) {
        BrdfSettings settings = BrdfSettings.thesis(Variant.NMM).with(b -> b.highestOrder(14).windowRadius(3)
                .windowPlacement(placement));
        DiffractionBrdf brdf = DiffractionBrdf.create(settings, field, TaylorTermComputer.compute(field, 14,
                Reporter.SILENT));
        double[][] uv = lookups();
        double[] out = new double[uv.length];
        for (int i = 0; i < uv.length; i++) {
            out[i] = brdf.xyz(LIGHT, Direction.fromProjected(-LIGHT.x() - uv[i][0], -LIGHT.y() - uv[i][1])).y();
        }
        return out;
    }

    /**
     * The lobes method's monochromatic power over a point footprint (pairs kept to 1e-12 when fixed; every lobe within
     * 10 standard deviations, so that the fixed window's half-texel lobes and the whole-texel ones reach as far; the
     * weights summed from the terms, as the fixed window's pairs are, rather than read from the table).
     */
    private static PatchSpectrum lobes(HeightField field, WindowPlacement placement) {
        BrdfSettings settings = BrdfSettings.thesis(Variant.LOBES).with(b -> b.highestOrder(14)
                .windowPlacement(placement).lobes(new LobeQuadrature(1e-12, 0.67, 8, 10.0, 8, 3, 0, 0)));
        return DiffractionBrdf.create(settings, field, TaylorTermComputer.compute(field, 14, Reporter.SILENT))
                .spectrum();
    }

    /** The fixed window's powers averaged over K x K cuts of the scan, L / K apart. */
    static double[] bruteForce(Function<HeightField, double[]> fixed, HeightField field) {
        return bruteForce(fixed, field, SHIFTS);
    }

    static double[] bruteForce(Function<HeightField, double[]> fixed, HeightField field, int shifts) {
        double[] sum = null;
        for (int a = 0; a < shifts; a++) {
            for (int b = 0; b < shifts; b++) {
                double[] p = fixed.apply(shifted(field, a * field.cols() / shifts, b * field.rows() / shifts));
                if (sum == null) {
                    sum = new double[p.length];
                }
                for (int i = 0; i < p.length; i++) {
                    sum[i] += p[i] / (shifts * shifts);
                }
            }
        }
        return sum;
    }

    @ParameterizedTest
    @EnumSource(Method.class)
    void theAveragedWindowIsTheFixedWindowAveragedOverWhereTheScanIsCut(Method method) {
        double[] averaged = powers(method, SCAN, WindowPlacement.AVERAGED);
        double[] brute = bruteForce(f -> powers(method, f, WindowPlacement.FIXED), SCAN);
        double largest = max(averaged);
        double worst = 0;
        for (int i = 0; i < averaged.length; i++) {
            worst = Math.max(worst, Math.abs(averaged[i] - brute[i]) / largest);
        }
        TestReport.line(AveragedWindowTest.class, String.format(Locale.ROOT,
                "%s: averaged window against %d x %d cuts of the fixed window: largest difference %.2e of the peak %.3e",
                method, SHIFTS, SHIFTS, worst, largest));
        assertTrue(largest > 1e-4, method + ": the lookups should reach the orders");
        assertTrue(worst < tolerance(method), method + ": " + worst);
    }

    /**
     * The filtered reference (pixel boxes of a 64 x 64 map, exact wavelength integrals) on pixels across the ridge's
     * orders and the mirror, on a 30 um scan of 48 x 48 samples (sigma_f = 0.29 texels: the nearest pairs weigh 0.06,
     * fewer pairs for the fixed window's reference to sum than at 48 um) and 4 x 4 cuts (pairs 4 texels apart keep
     * their phase and weigh exp(-4^2 / (4 sigma^2)) = 1e-20).
     */
    @Test
    @Tag(diffract.jrtr.GlTestSupport.LONG_TAG) // a brute-force map: a long test
    void theFilteredReferenceAveragesAsTheBruteForceDoes() {
        HeightField scan = wideScan(48, 0.625);
        int size = 64;
        int[][] pixels = {{32, 35}, {31, 36}, {32, 47}};
        double[] averaged = referencePixels(scan, WindowPlacement.AVERAGED, size, pixels);
        double[] brute = bruteForce(f -> referencePixels(f, WindowPlacement.FIXED, size, pixels), scan, 4);
        double largest = max(averaged);
        double worst = 0;
        for (int i = 0; i < averaged.length; i++) {
            worst = Math.max(worst, Math.abs(averaged[i] - brute[i]) / largest);
        }
        TestReport.line(AveragedWindowTest.class, String.format(Locale.ROOT,
                "filtered reference: averaged against 4 x 4 cuts: largest difference %.2e of the largest value %.3e",
                worst, largest));
        assertTrue(largest > 1e-3, "the pixels should hold the orders: " + largest);
        // each map of the brute force is converged to the reference's own tolerance (1e-4 per pixel)
        assertTrue(worst < 3e-4, "filtered reference: " + worst);
    }

    static double[] referencePixels(HeightField field, WindowPlacement placement, int size, int[][] pixels) {
        BrdfSettings settings = BrdfSettings.thesis(Variant.REFERENCE).with(b -> b.windowPlacement(placement)
                .pixelFilter(PixelFilter.BOX));
        DiffractionBrdf brdf = DiffractionBrdf.create(settings, field, null);
        double[] out = new double[3 * pixels.length];
        for (int i = 0; i < pixels.length; i++) {
            Xyz xyz = brdf.mapPixel(LIGHT, pixels[i][0], pixels[i][1], size);
            out[3 * i] = xyz.x();
            out[3 * i + 1] = xyz.y();
            out[3 * i + 2] = xyz.z();
        }
        return out;
    }

    /** Cut anywhere, even between the brute force's cuts, the scan gives the same averaged BRDF. */
    @ParameterizedTest
    @EnumSource(Method.class)
    void aCyclicallyShiftedScanGivesTheSameAveragedBrdf(Method method) {
        double[] original = powers(method, SCAN, WindowPlacement.AVERAGED);
        double[] moved = powers(method, shifted(SCAN, 37, 101), WindowPlacement.AVERAGED);
        double largest = max(original);
        for (int i = 0; i < original.length; i++) {
            assertEquals(original[i], moved[i], tolerance(method) * largest, method + " lookup " + i);
        }
    }

    /**
     * The negative control: the fixed window's BRDF of this scan changes by a large fraction where the scan is cut,
     * and differs from the average; for a 10 um patch (nearest pair weight 5e-12) the two models agree.
     */
    @Test
    void theFixedWindowDependsOnWhereTheScanIsCut() {
        double[] here = powers(Method.EXACT, SCAN, WindowPlacement.FIXED);
        double[] there = powers(Method.EXACT, shifted(SCAN, 37, 101), WindowPlacement.FIXED);
        double[] averaged = powers(Method.EXACT, SCAN, WindowPlacement.AVERAGED);
        double largest = max(averaged);
        double moved = 0;
        double apart = 0;
        for (int i = 0; i < here.length; i++) {
            moved = Math.max(moved, Math.abs(here[i] - there[i]) / largest);
            apart = Math.max(apart, Math.abs(here[i] - averaged[i]) / largest);
        }
        TestReport.line(AveragedWindowTest.class, String.format(Locale.ROOT, "48 um scan, fixed window: moves by %.3f "
                + "of the peak when the scan is cut elsewhere, differs from the average by %.3f", moved, apart));
        assertTrue(moved > 0.05, "the fixed window should depend on the cut: " + moved);
        assertTrue(apart > 0.05, "the fixed window should differ from the average: " + apart);

        HeightField narrow = wideScan(32, 10.0 / 32);
        double[] fixed = powers(Method.EXACT, narrow, WindowPlacement.FIXED);
        double[] average = powers(Method.EXACT, narrow, WindowPlacement.AVERAGED);
        double peak = max(average);
        for (int i = 0; i < fixed.length; i++) {
            assertEquals(average[i], fixed[i], 1e-10 * peak, "10 um patch, lookup " + i);
        }
    }

    private static double max(double[] values) {
        double m = 0;
        for (double v : values) {
            m = Math.max(m, Math.abs(v));
        }
        return m;
    }
}
