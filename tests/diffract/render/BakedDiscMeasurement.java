package diffract.render;

import diffract.jrtr.GlTestSupport;
import diffract.optics.BrdfMap;
import diffract.optics.BrdfMapDifference;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.Direction;
import diffract.optics.HeightField;
import diffract.optics.LightProfile;
import diffract.optics.PatchCatalogue;
import diffract.optics.PixelFilter;
import diffract.optics.TaylorTerms;
import diffract.optics.Variant;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

/**
 * What the baked table loses under a disc light, a measurement run on request (docs/disc-lobes.sh,
 * {@code -Ddiffract.measure=baked-disc}): the table (of the point light, the disc integrated by the lookup,
 * {@link BakedDisc}) against the CPU lobes method under the same disc, 64 x 64 maps of the Elaphe-like patch and
 * the 10 um blazed grating at 0.53, 2, 4, 10 and 20 degrees, theta_i 0 and 30, with 257 and 513 samples along u and
 * v (13 along w); {@code -Ddiffract.measure.discs=4,10} picks the diameters. No assertion.
 */
class BakedDiscMeasurement {
    static final int SIZE = 64;

    @Test
    void theBakedTableUnderADiscAgainstTheLobesMethod() {
        Assumptions.assumeTrue("baked-disc".equals(System.getProperty("diffract.measure")), "measurement on request");
        GlTestSupport.assumeOffscreenGl();
        for (String name : new String[] {"elaphe-like", "blazed-10um"}) {
            HeightField patch = name.equals("elaphe-like") ? RenderTestSupport.ELAPHE_LIKE
                    : PatchCatalogue.named(name).build().meanSubtracted();
            measure(name, patch);
        }
    }

    private static void measure(String name, HeightField patch) {
        TaylorTerms terms = RenderTestSupport.terms(patch);
        double[] discs = java.util.Arrays.stream(System.getProperty("diffract.measure.discs", "0.53,2,4,10,20")
                .split(",")).mapToDouble(Double::parseDouble).toArray();
        for (double lightDeg : discs) {
            for (double thetaI : new double[] {0, 30}) {
                BrdfSettings disc = BrdfSettings.thesis(Variant.LOBES).with(b -> b.pixelFilter(PixelFilter.BOX)
                        .lightSizeDeg(lightDeg).lightProfile(LightProfile.DISC));
                // the Elaphe-like ridges' period lies along y, the grating's along x
                Direction wi = Direction.fromSphericalDeg(thetaI, patch == RenderTestSupport.ELAPHE_LIKE ? 90 : 0);
                float[] cpu = BrdfMap.xyz(DiffractionBrdf.create(disc, patch, terms), wi, SIZE, Reporter.SILENT);
                StringBuilder line = new StringBuilder(String.format(java.util.Locale.ROOT,
                        "%s, 65 um, %d px, %.2f-degree disc, theta_i %.0f: the baked table against the CPU "
                                + "lobes method, lit mean / p95", name, SIZE, lightDeg, thetaI));
                for (int uvSamples : new int[] {257, 513}) {
                    BrdfSettings baked = disc.with(b -> b.variant(Variant.BAKED).bakedSamples(uvSamples, 13));
                    BrdfMapDifference d = RenderTestSupport.difference(cpu, RenderTestSupport.gpuXyz(terms, baked, wi,
                            SIZE), SIZE, wi);
                    line.append(String.format(java.util.Locale.ROOT, "; %d x %d x 13: %.2f / %.2f", uvSamples,
                            uvSamples, d.lit().mean(), d.lit().p95()));
                }
                TestReport.line(BakedDiscMeasurement.class, line.toString());
            }
        }
    }
}
