package diffract.render;

import diffract.jrtr.GlTestSupport;
import diffract.optics.maps.AutoExposure;
import diffract.optics.BakedGrid;
import diffract.optics.BrdfMap;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.settings.LightProfile;
import diffract.optics.patches.PatchCatalogue;
import diffract.optics.settings.PixelFilter;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.Variant;
import diffract.util.MeasureProperties;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

/**
 * What the baked table loses under a disc light, a measurement run on request (docs/measurements/disc-lobes.sh,
 * {@code -Ddiffract.measure=baked-disc}): the table (of the point light, the disc integrated by the lookup,
 * {@link BakedDisc}) against the CPU lobes method under the same disc, 64 x 64 maps of the Elaphe-like patch, the
 * 10 um blazed grating and the Elaphe-like skin at AFM size (elaphe-scan) at 0.53, 2, 4, 10 and 20 degrees,
 * theta_i 0 and 30, with 257 and 513 samples along u and v and the automatic grid along w. Properties pick parts:
 * {@code -Ddiffract.measure.discs=4,10} the diameters, {@code -Ddiffract.measure.patches=elaphe-scan} the patches
 * of the catalogue, {@code -Ddiffract.measure.grids=513} and {@code -Ddiffract.measure.wSamples=25} the grid. Both
 * maps are drawn for the exposure of the lobes method's first map, as brdfmap draws them (LobeQuadrature.shownAt).
 * No assertion.
 */
class BakedDiscMeasurement {
    static final int SIZE = 64;
    /** The table's samples along u and v: {@code -Ddiffract.measure.grids=513} picks them. */
    static final int[] GRIDS = MeasureProperties.ints("diffract.measure.grids", "257,513");
    /** The table's samples along w: {@code -Ddiffract.measure.wSamples=25}; 0, the default, the automatic grid. */
    static final int W_SAMPLES = Integer.getInteger("diffract.measure.wSamples", 0);

    @Test
    void theBakedTableUnderADiscAgainstTheLobesMethod() {
        Assumptions.assumeTrue("baked-disc".equals(System.getProperty("diffract.measure")), "measurement on request");
        GlTestSupport.assumeOffscreenGl();
        String patches = System.getProperty("diffract.measure.patches", "elaphe-like,blazed-10um,elaphe-scan");
        for (String name : patches.split(",")) {
            HeightField patch = name.equals("elaphe-like") ? RenderTestSupport.ELAPHE_LIKE
                    : PatchCatalogue.named(name).build().meanSubtracted();
            measure(name, patch, PatchCatalogue.named(name).phiIDeg());
        }
    }

    private static void measure(String name, HeightField patch, double phiIDeg) {
        TaylorTerms terms = RenderTestSupport.terms(patch);
        for (double lightDeg : MeasureProperties.doubles("diffract.measure.discs", "0.53,2,4,10,20")) {
            for (double thetaI : new double[] {0, 30}) {
                BrdfSettings asked = BrdfSettings.thesis(Variant.LOBES).with(b -> b.pixelFilter(PixelFilter.BOX)
                        .lightSizeDeg(lightDeg).lightProfile(LightProfile.DISC));
                Direction wi = Direction.fromSphericalDeg(thetaI, phiIDeg);
                // as brdfmap --exposure auto: both maps drawn for the exposure of the first (LobeQuadrature.shownAt)
                float[] first = BrdfMap.xyz(DiffractionBrdf.create(asked, patch, terms), wi, SIZE, Reporter.SILENT);
                BrdfSettings disc = asked.shownAt(AutoExposure.ofXyz(first, wi, SIZE));
                float[] cpu = disc == asked ? first
                        : BrdfMap.xyz(DiffractionBrdf.create(disc, patch, terms), wi, SIZE, Reporter.SILENT);
                StringBuilder line = new StringBuilder(String.format(java.util.Locale.ROOT,
                        "%s, 65 um, %d px, %.2f-degree disc, theta_i %.0f: the baked table against the CPU "
                                + "lobes method, lit mean / p95", name, SIZE, lightDeg, thetaI));
                for (int uvSamples : GRIDS) {
                    BrdfSettings baked = disc.with(b -> b.variant(Variant.BAKED).bakedSamples(uvSamples, W_SAMPLES));
                    int wSamples = BakedGrid.of(baked, terms.maxAbsHeightUm()).wSamples();
                    BrdfMapDifference d = RenderTestSupport.difference(cpu, RenderTestSupport.gpuXyz(terms, baked, wi,
                            SIZE), SIZE, wi);
                    line.append(String.format(java.util.Locale.ROOT, "; %d x %d x %d: %.2f / %.2f", uvSamples,
                            uvSamples, wSamples, d.lit().mean(), d.lit().p95()));
                }
                TestReport.line(BakedDiscMeasurement.class, line.toString());
            }
        }
    }
}
