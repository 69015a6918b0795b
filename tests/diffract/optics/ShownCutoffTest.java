package diffract.optics;

import diffract.optics.patches.Direction;
import diffract.optics.maps.AutoExposure;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.PatchCatalogue;
import diffract.optics.settings.PixelFilter;
import diffract.optics.spectra.TaylorTerms;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The lobes method's cutoff holds what a skipped lobe shows on the display: a map shown brighter than
 * {@link LobeQuadrature#CUTOFF_EXPOSURE} is drawn with the cutoff scaled down by its exposure. A point light's narrow
 * orders at 65 um, point-sampled in a 64 x 64 map, are dim (its brightest diffracted pixel 1e-4 of white): shown at
 * their own exposure (about 10^4, as the bench compares them), the unscaled cutoff loses lobes the display shows at a
 * tenth of white.
 */
class ShownCutoffTest {
    private static final int SIZE = 64;

    @Test
    void theCutoffScalesDownWithABrighterExposureOnly() {
        LobeQuadrature q = LobeQuadrature.DEFAULT;
        assertSame(q, q.shownAt(1));
        assertSame(q, q.shownAt(LobeQuadrature.CUTOFF_EXPOSURE));
        assertEquals(q.cutoff() / 100, q.shownAt(100 * LobeQuadrature.CUTOFF_EXPOSURE).cutoff(), 1e-20);
        assertEquals(q.nodesPerSigma(), q.shownAt(1e4).nodesPerSigma());
        LobeQuadrature none = new LobeQuadrature(1e-4, 0.67, 8, 4.0, 8, 3, 0, 1e-4);
        assertSame(none, none.shownAt(1e4), "no cutoff stays none");
        BrdfSettings s = BrdfSettings.thesis(Variant.LOBES);
        assertSame(s, s.shownAt(10));
        assertEquals(q.cutoff() * LobeQuadrature.CUTOFF_EXPOSURE / 3000, s.shownAt(3000).lobes().cutoff(), 1e-20);
    }

    /**
     * Shown at one exposure and then at another, a quadrature holds the second's cutoff: a scene is drawn for its
     * exposure and then shown at it, a viewer's exposure keys move it up and down.
     */
    @Test
    void showingAgainScalesTheCutoffAsAskedNotTheShownOne() {
        LobeQuadrature q = LobeQuadrature.DEFAULT;
        double e = LobeQuadrature.CUTOFF_EXPOSURE;
        LobeQuadrature shown = q.shownAt(45 * e);
        assertEquals(q.cutoff() / 45, shown.cutoff(), 1e-20);
        assertSame(shown, shown.shownAt(45 * e), "the same exposure again changes nothing");
        assertEquals(q.cutoff() / 10, shown.shownAt(10 * e).cutoff(), 1e-20);
        assertEquals(q.cutoff() / 1000, shown.shownAt(1000 * e).cutoff(), 1e-20);
        assertEquals(q, shown.shownAt(1), "shown dim again: the cutoff as asked");
        assertEquals(q.shownAt(10 * e), shown.shownAt(10 * e));
        assertEquals(q.cutoff(), shown.askedCutoff());
        BrdfSettings s = BrdfSettings.thesis(Variant.LOBES).shownAt(1353.76);
        assertSame(s, s.shownAt(1353.76));
    }

    /** The bench's case: blazed grating, 65 um, point light and point pixels, theta_i 45 degrees. */
    @Test
    void aDimMapShownAtItsOwnExposureKeepsItsLobes() {
        HeightField field = PatchCatalogue.named("blazed-10um").spec().build().meanSubtracted();
        BrdfSettings base = BrdfSettings.thesis(Variant.REFERENCE).with(b -> b.lightSizeDeg(0)
                .pixelFilter(PixelFilter.POINT));
        Direction wi = Direction.fromSphericalDeg(45, 0);
        float[] reference = BrdfMap.xyz(DiffractionBrdf.create(base, field, null), wi, SIZE, Reporter.SILENT);
        double exposure = AutoExposure.ofXyz(reference, wi, SIZE);
        assertTrue(exposure > 1e3, "a dim map: exposure " + exposure);
        BrdfSettings lobes = base.with(b -> b.variant(Variant.LOBES).highestOrder(20));
        TaylorTerms terms = TaylorTermComputer.compute(field, 20, Reporter.SILENT);
        double shown = litMean(reference, lobes.shownAt(exposure), field, terms, wi, exposure);
        double unscaled = litMean(reference, lobes, field, terms, wi, exposure);
        TestReport.line(ShownCutoffTest.class, String.format(java.util.Locale.ROOT, "blazed-10um at 65 um, point light,"
                + " 64 px, theta_i 45, shown at exposure %.3g: lit mean CIEDE2000 %.3f with the cutoff scaled, %.3f"
                + " without", exposure, shown, unscaled));
        assertTrue(shown < 0.3, "scaled: " + shown);
        assertTrue(unscaled > 3, "the unscaled cutoff loses visible lobes: " + unscaled);
    }

    private static double litMean(float[] reference, BrdfSettings settings, HeightField field, TaylorTerms terms,
                                  Direction wi, double exposure) {
        float[] map = BrdfMap.xyz(DiffractionBrdf.create(settings, field, terms), wi, SIZE, Reporter.SILENT);
        return BrdfMapDifference.of(reference, map, SIZE, exposure).lit().mean();
    }
}
