package diffract.render;

import diffract.jrtr.GlTestSupport;
import diffract.optics.BrdfSettings;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.settings.LightProfile;
import diffract.optics.settings.PixelFilter;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.Variant;
import diffract.util.MeasureProperties;
import diffract.util.TestReport;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

import java.util.Arrays;

/**
 * What a disc light costs the lobes shader, a measurement run on request (docs/measurements/disc-lobes.sh,
 * {@code -Ddiffract.measure=disc-speed}): GL time per 64 x 64 map at the thesis' 65 um coherence, theta_i = 30
 * degrees, of the lobes method under a disc and under the Gaussian profile of the same diameter and of the baked
 * table under the disc (what the commands take at 65 um: 513 samples along u and v, the automatic w grid, 25 on the
 * Elaphe-like patch and 14 on the grating), against FLSS in the thesis' configuration on the same context, in
 * alternating rounds (the median of each), so that the machine's load moves all alike;
 * {@code -Ddiffract.measure.discs=4,10} picks the diameters. No assertion: speed is reported, never tested.
 */
class DiscLobesSpeedMeasurement {
    /** 64 by default; a fast GPU finishes such a map in microseconds, so {@code -Ddiffract.measure.size} sets it. */
    static final int SIZE = Integer.getInteger("diffract.measure.size", 64);
    static final int ROUNDS = 2;
    static final int FRAMES = 10;

    @Test
    void lobesUnderADiscAgainstTheGaussianProfileAndFlss() {
        Assumptions.assumeTrue("disc-speed".equals(System.getProperty("diffract.measure")), "measurement on request");
        GlTestSupport.assumeOffscreenGl();
        measure("blazed", RenderTestSupport.BLAZED);
        measure("elaphe-like", RenderTestSupport.ELAPHE_LIKE);
    }

    private static void measure(String name, HeightField patch) {
        TaylorTerms terms = RenderTestSupport.terms(patch);
        Direction wi = RenderTestSupport.light(patch, 30);
        BrdfSettings flss = BrdfSettings.thesis(Variant.FLSS);
        for (double lightDeg : MeasureProperties.doubles("diffract.measure.discs", "0.53,2,4,10,20")) {
            BrdfSettings disc = BrdfSettings.thesis(Variant.LOBES).with(b -> b.pixelFilter(PixelFilter.BOX)
                    .lightSizeDeg(lightDeg).lightProfile(LightProfile.DISC));
            BrdfSettings gaussian = disc.with(b -> b.lightProfile(LightProfile.GAUSSIAN));
            BrdfSettings baked = disc.with(b -> b.variant(Variant.BAKED).bakedSamples(513, 0));
            double[] discMs = new double[ROUNDS];
            double[] bakedMs = new double[ROUNDS];
            double[] gaussianMs = new double[ROUNDS];
            double[] flssMs = new double[ROUNDS];
            try (GpuBrdfMap d = new GpuBrdfMap(terms, disc); GpuBrdfMap g = new GpuBrdfMap(terms, gaussian);
                 GpuBrdfMap t = new GpuBrdfMap(terms, baked); GpuBrdfMap f = new GpuBrdfMap(terms, flss)) {
                for (int r = 0; r < ROUNDS; r++) {
                    discMs[r] = d.medianMsPerFrame(wi, SIZE, 1, FRAMES);
                    gaussianMs[r] = g.medianMsPerFrame(wi, SIZE, 1, FRAMES);
                    bakedMs[r] = t.medianMsPerFrame(wi, SIZE, 1, FRAMES);
                    flssMs[r] = f.medianMsPerFrame(wi, SIZE, 1, FRAMES);
                }
            }
            double dm = median(discMs);
            double gm = median(gaussianMs);
            double fm = median(flssMs);
            double tm = median(bakedMs);
            TestReport.line(DiscLobesSpeedMeasurement.class, String.format(java.util.Locale.ROOT,
                    "%s, 65 um, %d px, %.2f deg: lobes under the disc %.1f ms, under the Gaussian %.1f ms, the baked "
                            + "table under the disc %.1f ms, FLSS (thesis) %.1f ms: FLSS / disc %.1f, disc / Gaussian "
                            + "%.2f, FLSS / baked %.1f", name, SIZE, lightDeg, dm, gm, tm, fm, fm / dm, dm / gm,
                    fm / tm));
        }
    }

    private static double median(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        return s[s.length / 2];
    }
}
