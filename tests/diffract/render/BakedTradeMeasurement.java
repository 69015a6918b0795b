package diffract.render;

import diffract.util.TestReport;
import diffract.jrtr.GlTestSupport;
import diffract.optics.BrdfMap;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.Variant;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import java.util.Locale;

/**
 * The measurements of docs/measurements/baked.md (not a test: it asserts nothing and runs only with
 * {@code -Ddiffract.measure=baked}): memory, bake time, CIEDE2000 against the CPU reference map (theta_i 0, 45,
 * 75) and GPU ms/frame of the baked table against FLSS in the thesis' configuration (30 terms, 5 nm, 3 x 3) on
 * the same run, for the blazed grating and the Elaphe-like patch of docs/measurements/gpu-figures.sh, at the thesis'
 * coherence length (65 um) and at 10 um. Prints markdown rows.
 *
 * <pre>xvfb-run -a mvn -q test -Dtest=BakedTradeMeasurement -Ddiffract.measure=baked</pre>
 */
@Tag("gl")
class BakedTradeMeasurement {
    static final int SIZE = 128;

    @Test
    void measure() {
        Assumptions.assumeTrue("baked".equals(System.getProperty("diffract.measure")), "measurement only on request");
        GlTestSupport.assumeOffscreenGl();
        HeightField blazed = SyntheticPatches.blazed(2.5, 0.2, 25, 26, 16).meanSubtracted();
        HeightField elaphe = SyntheticPatches.elapheLike().meanSubtracted();
        String grids = System.getProperty("diffract.bakedGrids", "128,256");
        TestReport.line(BakedTradeMeasurement.class, "| patch | 4 sigma_s | table (u x v x w) | GPU MB | bake s | theta_i | flss ms | baked ms | "
                + "speed-up | flss: lit mean / p95 | baked: lit mean / p95 | baked vs flss: lit mean / p95 |");
        TestReport.line(BakedTradeMeasurement.class, "|---|---|---|---|---|---|---|---|---|---|---|---|");
        for (double coherenceUm : new double[] {10, 65}) {
            for (HeightField patch : new HeightField[] {blazed, elaphe}) {
                for (String grid : grids.split(",")) {
                    measure(patch, patch == elaphe ? "elaphe-like" : "blazed", patch == elaphe ? 90 : 0,
                            patch == elaphe ? 25 : 15, coherenceUm, Integer.parseInt(grid.trim()));
                }
            }
        }
    }

    private static void measure(HeightField patch, String name, double phiDeg, double exposure, double coherenceUm,
                                int uvSamples) {
        TaylorTerms terms = TaylorTermComputer.compute(patch, 30, Reporter.SILENT);
        BrdfSettings flss = BrdfSettings.thesis(Variant.FLSS).with(b -> b.coherenceLengthUm(4 * (coherenceUm / 4.0)));
        BrdfSettings baked = flss.with(b -> b.variant(Variant.BAKED)).with(b -> b.bakedSamples(uvSamples, 0));
        DiffractionBrdf reference = DiffractionBrdf.create(flss.with(b -> b.variant(Variant.REFERENCE)), patch, null);
        try (GpuBrdfMap flssMap = new GpuBrdfMap(terms, flss);
             GpuBrdfMap bakedMap = new GpuBrdfMap(terms, baked)) {
            BakedTable table = bakedMap.bakedTable();
            for (double thetaI : new double[] {0, 45, 75}) {
                Direction wi = Direction.fromSphericalDeg(thetaI, phiDeg);
                float[] ref = BrdfMap.xyz(reference, wi, SIZE, Reporter.SILENT);
                float[] f = flssMap.xyz(wi, SIZE);
                float[] b = bakedMap.xyz(wi, SIZE);
                double flssMs = flssMap.medianMsPerFrame(wi, SIZE, 1, 10);
                double bakedMs = bakedMap.medianMsPerFrame(wi, SIZE, 2, 10);
                BrdfMapDifference fr = BrdfMapDifference.of(ref, f, SIZE, exposure);
                BrdfMapDifference br = BrdfMapDifference.of(ref, b, SIZE, exposure);
                BrdfMapDifference bf = BrdfMapDifference.of(f, b, SIZE, exposure);
                TestReport.line(BakedTradeMeasurement.class, String.format(Locale.ROOT,
                        "| %s | %.0f um | %d x %d x %d | %.1f | %.1f | %.0f | %.1f | %.2f | %.0f | %.2f / %.2f | "
                                + "%.2f / %.2f | %.2f / %.2f |",
                        name, coherenceUm, table.grid().uvSamples(), table.grid().uvSamples(), table.grid().wSamples(),
                        table.gpuBytes() / 1e6, table.bakeSeconds(), thetaI, flssMs, bakedMs, flssMs / bakedMs,
                        fr.lit().mean(), fr.lit().p95(), br.lit().mean(), br.lit().p95(), bf.lit().mean(),
                        bf.lit().p95()));
            }
        }
    }
}
