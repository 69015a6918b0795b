package diffract.viewer;

import diffract.optics.BrdfSettings;
import diffract.optics.settings.PixelFilter;
import diffract.optics.spectra.TaylorExpansion;
import diffract.optics.Variant;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The preview's settings: one place, cheap, and the same terms and expansion as the settings it previews. */
class PreviewPolicyTest {
    @Test
    void aTaylorVariantIsPreviewedByFlssOnOneTexelAndCoarseWavelengths() {
        for (Variant v : new Variant[] {Variant.FLSS, Variant.NMM, Variant.PQ}) {
            BrdfSettings configured = BrdfSettings.builder(v).highestOrder(30).lambdaStepNm(5).windowRadius(2)
                    .expansion(TaylorExpansion.CENTRED).coherenceLengthUm(65).build();
            BrdfSettings preview = PreviewPolicy.settings(configured, false);
            assertEquals(Variant.FLSS, preview.variant());
            assertEquals(0, preview.window().radius());
            assertEquals(PreviewPolicy.LAMBDA_STEP_NM, preview.spectral().lambdaStepNm());
            // what decides where the orders land stays: the terms, the expansion, the range, the coherence
            assertEquals(configured.taylor(), preview.taylor());
            assertEquals(configured.spectral().lambdaMinNm(), preview.spectral().lambdaMinNm());
            assertEquals(configured.spectral().lambdaMaxNm(), preview.spectral().lambdaMaxNm());
            assertEquals(configured.illumination(), preview.illumination());
        }
        BrdfSettings coarse = BrdfSettings.builder(Variant.FLSS).lambdaStepNm(50).build();
        assertEquals(50, PreviewPolicy.settings(coarse, false).spectral().lambdaStepNm());
    }

    @Test
    void aFilteringVariantUnderTheSunIsPreviewedUnderAPointLight() {
        BrdfSettings lobes = BrdfSettings.builder(Variant.LOBES).lightSizeDeg(0.53).pixelFilter(PixelFilter.BOX)
                .coherenceLengthUm(65).build();
        BrdfSettings preview = PreviewPolicy.settings(lobes, false);
        assertEquals(Variant.FLSS, preview.variant());
        assertTrue(preview.illumination().light().isPoint(), "FLSS samples the light at its centre");
        assertEquals(PixelFilter.POINT, preview.illumination().pixelFilter());
        assertEquals(65, preview.illumination().coherenceLengthUm(), 1e-12);
        assertEquals(lobes.illumination().gain(), preview.illumination().gain());
    }

    @Test
    void theBakedTablePreviewsItselfOnceBaked() {
        BrdfSettings baked = BrdfSettings.builder(Variant.BAKED).highestOrder(20).lambdaStepNm(5).build();
        assertSame(baked, PreviewPolicy.settings(baked, true));
        BrdfSettings whileBaking = PreviewPolicy.settings(baked, false);
        assertEquals(Variant.FLSS, whileBaking.variant());
        assertEquals(0, whileBaking.window().radius());
    }
}
