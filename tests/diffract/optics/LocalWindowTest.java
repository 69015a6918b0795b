package diffract.optics;

import diffract.optics.patches.HeightField;
import diffract.optics.spectra.PatchSpectrum;
import diffract.optics.spectra.TaylorGaussianSpectrum;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.windows.CoherenceWindow;
import diffract.optics.windows.LocalWindow;
import diffract.optics.windows.SkinFootprint;
import diffract.optics.windows.WindowPlacement;
import diffract.optics.windows.WindowRadii;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Test;

import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The window under one surface point ({@link LocalWindow}) against what it claims to be: with no footprint, the
 * windowed transform of the periodic scan at x0 summed directly from exact exponentials (brute force in space), and at
 * x0 = 0 the thesis' fixed window; averaged over x0 on a grid across the scan, the averaged window; with a footprint
 * that covers a period (a box of width L, a Gaussian of 2 L), the averaged window; with a small footprint, neither.
 *
 * <p>The scan: 64 x 64 samples 0.5 um apart (32 um, sigma_f = 0.31 texels at 65 um: the nearest texel pairs weigh
 * exp(-1 / (4 sigma^2)) = 0.08, so the pairs matter), |P|^2 at 550 nm around the ridge's first order and the mirror.
 */
class LocalWindowTest {
    static final HeightField SCAN = WideScan.of(64, 0.5);
    static final double LAMBDA_UM = 0.55;
    static final int ORDERS = 16;
    static final TaylorTerms TERMS = TaylorTermComputer.compute(SCAN, ORDERS, Reporter.SILENT);
    static final CoherenceWindow WINDOW = CoherenceWindow.thesis();
    static final double EXTENT_UM = 32.0;
    static final double W = -(AveragedWindowTest.LIGHT.z() + 0.95);

    static TaylorGaussianSpectrum spectrum(WindowPlacement placement) {
        return new TaylorGaussianSpectrum(TERMS, ORDERS, new WindowRadii(3, 3), 0.0, WINDOW.placed(placement));
    }

    static double[] powers(PatchSpectrum spectrum) {
        double[][] uv = AveragedWindowTest.lookups();
        double[] out = new double[uv.length];
        for (int i = 0; i < uv.length; i++) {
            out[i] = spectrum.power(uv[i][0], uv[i][1], W, LAMBDA_UM);
        }
        return out;
    }

    static double[] local(double x0Um, double y0Um, SkinFootprint footprint) {
        return powers(spectrum(WindowPlacement.LOCAL).under(new LocalWindow(x0Um, y0Um, footprint)));
    }

    /**
     * |P(f; x0)|^2 summed in space: the window g(x - x0) = exp(-|x - x0|^2 / (2 sigma_s^2)) over the periodic scan's
     * samples, exp(i k w h) exactly, times exp(2 pi i f . x) (Stam's transform, f = (u, v) / lambda), normalised by
     * the window's integral 2 pi sigma_s^2 so that a flat mirror's peak is 1; out to 7 sigma_s, where g is 2e-11.
     */
    static double bruteForce(double u, double v, double x0Um, double y0Um) {
        double sigmaUm = WINDOW.sigmaSpatialUm();
        double reach = 7 * sigmaUm;
        double pixel = SCAN.pixelSizeXUm();
        double a = 2 * Math.PI / LAMBDA_UM * W;
        double fx = u / LAMBDA_UM;
        double fy = v / LAMBDA_UM;
        double re = 0;
        double im = 0;
        int first = (int) Math.floor((-reach) / pixel);
        int last = (int) Math.ceil(reach / pixel);
        int baseX = (int) Math.round(x0Um / pixel);
        int baseY = (int) Math.round(y0Um / pixel);
        for (int j = first; j <= last; j++) {
            int row = baseY + j;
            double y = row * pixel;
            double gy = Math.exp(-0.5 * Math.pow((y - y0Um) / sigmaUm, 2));
            for (int i = first; i <= last; i++) {
                int col = baseX + i;
                double x = col * pixel;
                double g = gy * Math.exp(-0.5 * Math.pow((x - x0Um) / sigmaUm, 2));
                double h = SCAN.heightUm(Math.floorMod(row, SCAN.rows()), Math.floorMod(col, SCAN.cols()));
                double phase = a * h + 2 * Math.PI * (fx * x + fy * y);
                re += g * Math.cos(phase);
                im += g * Math.sin(phase);
            }
        }
        double norm = pixel * pixel / (2 * Math.PI * sigmaUm * sigmaUm);
        return (re * re + im * im) * norm * norm;
    }

    static double max(double[] values) {
        double m = 0;
        for (double v : values) {
            m = Math.max(m, v);
        }
        return m;
    }

    /** The largest |a - b| of the peak of b. */
    static double difference(double[] a, double[] b) {
        double worst = 0;
        for (int i = 0; i < a.length; i++) {
            worst = Math.max(worst, Math.abs(a[i] - b[i]));
        }
        return worst / max(b);
    }

    static void report(String line) {
        TestReport.line(LocalWindowTest.class, line);
    }

    @Test
    void withoutAFootprintItIsTheWindowAtX0SummedFromExactExponentials() {
        double[][] uv = AveragedWindowTest.lookups();
        double[][] places = {{0, 0}, {7.3, 0}, {0, 11.9}, {13.25, 21.5}, {-40.1, 77.7}};
        for (double[] x0 : places) {
            double[] local = local(x0[0], x0[1], SkinFootprint.POINT);
            double[] brute = new double[uv.length];
            for (int i = 0; i < uv.length; i++) {
                brute[i] = bruteForce(uv[i][0], uv[i][1], x0[0], x0[1]);
            }
            double d = difference(local, brute);
            report(String.format(Locale.ROOT, "x0 = (%.2f, %.2f) um, no footprint: against the direct sum of exact"
                    + " exponentials %.2e of the peak %.3e", x0[0], x0[1], d, max(brute)));
            assertTrue(max(brute) > 1e-3, "the lookups should reach the orders");
            // float32 terms, N = 16 at x = k |w| max|h| = 3.6: a few 1e-7 of the peak
            assertTrue(d < 1e-5, "x0 = " + x0[0] + ", " + x0[1] + ": " + d);
        }
        // the negative control: the window moved by a third of the scan changes |P|^2 by far more than that
        double moved = difference(local(EXTENT_UM / 3, EXTENT_UM / 5, SkinFootprint.POINT),
                local(0, 0, SkinFootprint.POINT));
        report(String.format(Locale.ROOT, "x0 moved by (L / 3, L / 5): |P|^2 changes by %.2e of the peak", moved));
        assertTrue(moved > 1e-3, "moving the window should change the BRDF of a scan wider than the window: " + moved);
    }

    @Test
    void atTheOriginWithoutAFootprintItIsTheThesisFixedWindow() {
        double d = difference(local(0, 0, SkinFootprint.POINT), powers(spectrum(WindowPlacement.FIXED)));
        double period = difference(local(EXTENT_UM, -2 * EXTENT_UM, SkinFootprint.POINT),
                powers(spectrum(WindowPlacement.FIXED)));
        report(String.format(Locale.ROOT, "x0 = 0 and x0 = (L, -2L): against the fixed window %.2e and %.2e of the"
                + " peak", d, period));
        assertTrue(d < 1e-13, "x0 = 0: " + d);
        assertTrue(period < 1e-12, "a whole period on: " + period);
    }

    @Test
    void averagedOverX0AcrossTheScanItIsTheAveragedWindow() {
        int k = 8; // pairs 8 texels apart keep their phase: they weigh exp(-64 / (4 sigma^2)) = 1e-71
        double[] mean = null;
        for (int a = 0; a < k; a++) {
            for (int b = 0; b < k; b++) {
                double[] p = local((a + 0.37) * EXTENT_UM / k, (b + 0.61) * EXTENT_UM / k, SkinFootprint.POINT);
                if (mean == null) {
                    mean = new double[p.length];
                }
                for (int i = 0; i < p.length; i++) {
                    mean[i] += p[i] / (k * k);
                }
            }
        }
        double[] averaged = powers(spectrum(WindowPlacement.AVERAGED));
        double d = difference(mean, averaged);
        report(String.format(Locale.ROOT, "mean over %d x %d window centres across the scan: against the averaged"
                + " window %.2e of the peak", k, k, d));
        assertTrue(d < 1e-13, "mean over x0: " + d);
    }

    @Test
    void aFootprintThatCoversThePeriodGivesTheAveragedWindow() {
        double[] averaged = powers(spectrum(WindowPlacement.AVERAGED));
        double box = difference(local(5.1, 17.3, SkinFootprint.box(EXTENT_UM, EXTENT_UM)), averaged);
        double gaussian = difference(local(5.1, 17.3, SkinFootprint.gaussian(2 * EXTENT_UM)), averaged);
        double small = difference(local(5.1, 17.3, SkinFootprint.gaussian(0.1 * EXTENT_UM)), averaged);
        double halfBox = difference(local(5.1, 17.3, SkinFootprint.box(EXTENT_UM / 2, EXTENT_UM / 2)), averaged);
        report(String.format(Locale.ROOT, "footprints against the averaged window, of the peak: box L %.2e, Gaussian"
                + " 2 L %.2e; box L / 2 %.2e, Gaussian 0.1 L %.2e", box, gaussian, halfBox, small));
        assertTrue(box < 1e-13, "box of width L: " + box);
        assertTrue(gaussian < 1e-13, "Gaussian of 2 L: " + gaussian);
        // negative controls: footprints smaller than the period keep pairs
        assertTrue(small > 1e-3, "Gaussian of 0.1 L: " + small);
        assertTrue(halfBox > 1e-3, "box of L / 2: " + halfBox);
    }
}
