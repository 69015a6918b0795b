package diffract.render;

import diffract.jrtr.GlTestSupport;
import diffract.optics.BrdfSettings;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.LobeQuadrature;
import diffract.optics.patches.PatchCatalogue;
import diffract.optics.settings.PixelFilter;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.Variant;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

/**
 * What the lobes method's cutoff buys on the 52 um scan, a measurement run on request (docs/measurements/scans.md,
 * {@code -Ddiffract.measure=scan-cutoff}): GL time per 256 x 256 map (whose pixels are marched lobe by lobe) at 65 um,
 * theta_i = 30, a point light, of the lobes method at its default cutoff (1e-6 of white) and at 3, 10 and 100 times
 * it, against FLSS in the thesis' configuration on the same context (medians of alternating rounds). No
 * assertion: speed is reported, never tested.
 */
class ScanLobesSpeedMeasurement {
    static final int SIZE = 256;
    static final int FRAMES = 10;

    @Test
    void lobesAgainstFlssOnTheScanAtCoarserCutoffs() {
        Assumptions.assumeTrue("scan-cutoff".equals(System.getProperty("diffract.measure")), "measurement on request");
        GlTestSupport.assumeOffscreenGl();
        PatchCatalogue.Entry entry = PatchCatalogue.named("elaphe-scan");
        HeightField scan = entry.build().meanSubtracted();
        TaylorTerms terms = TaylorTermComputer.compute(scan, 30, Reporter.SILENT);
        Direction wi = Direction.fromSphericalDeg(30, entry.phiIDeg());
        BrdfSettings flss = BrdfSettings.thesis(Variant.FLSS).with(b -> b.lightSizeDeg(0)
                .pixelFilter(PixelFilter.POINT));
        LobeQuadrature d = LobeQuadrature.DEFAULT;
        try (GpuBrdfMap f = new GpuBrdfMap(terms, flss)) {
            for (double cutoff : new double[] {d.cutoff(), 3 * d.cutoff(), 10 * d.cutoff(), 100 * d.cutoff()}) {
                // the march over lobes, whose cost the cutoff sets
                LobeQuadrature q = new LobeQuadrature(d.pairThreshold(), d.nodesPerSigma(), d.maxStepNm(),
                        d.reachSigmas(), d.weightStepNm(), d.lightNodes(), cutoff, d.weightTolerance(), 0);
                BrdfSettings lobes = BrdfSettings.thesis(Variant.LOBES).with(b -> b.pixelFilter(PixelFilter.BOX)
                        .lightSizeDeg(0).lobes(q));
                try (GpuBrdfMap l = new GpuBrdfMap(terms, lobes)) {
                    double lm = l.medianMsPerFrame(wi, SIZE, 1, FRAMES);
                    double fm = f.medianMsPerFrame(wi, SIZE, 1, FRAMES);
                    TestReport.line(ScanLobesSpeedMeasurement.class, String.format(java.util.Locale.ROOT,
                            "elaphe-scan, 65 um, %d px, cutoff %.0e of white: lobes %.1f ms, FLSS (thesis) %.1f ms: "
                                    + "FLSS / lobes %.1f", SIZE, cutoff, lm, fm, fm / lm));
                }
            }
        }
    }
}
