package diffract.render;

import diffract.jrtr.Material;
import diffract.jrtr.UniformValue;
import diffract.optics.BrdfSettings;
import diffract.optics.LobeQuadrature;
import diffract.optics.Variant;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

/**
 * A display material shown at a new exposure (the viewer's exposure keys): the tone map takes it, and the lobes
 * method's cutoff follows it as {@link LobeQuadrature#shownAt} scales it, so that a brighter picture keeps the dim
 * lobes it now shows; a method without a cutoff gets the tone map alone.
 */
class DisplayExposureTest {
    @Test
    void theLobesCutoffFollowsTheExposure() {
        BrdfSettings lobes = BrdfSettings.thesis(Variant.LOBES);
        double base = lobes.lobes().cutoff();
        assertEquals(LobeQuadrature.DEFAULT_CUTOFF, base);
        Material m = new Material(null);
        DiffractionMaterials.setExposure(m, lobes, 300);
        assertEquals(300f, value(m, "exposure"));
        // ten times the exposure at which the default cutoff is a third of a display step: a tenth of the cutoff
        assertEquals(base * LobeQuadrature.CUTOFF_EXPOSURE / 300, value(m, "lobeCutoff"), 1e-6 * base);
        DiffractionMaterials.setExposure(m, lobes, 3);
        assertEquals((float) base, value(m, "lobeCutoff"), "a dim picture keeps the cutoff");
    }

    @Test
    void flssTakesTheToneMapAlone() {
        Material m = new Material(null);
        DiffractionMaterials.setExposure(m, BrdfSettings.thesis(Variant.FLSS), 300);
        assertEquals(300f, value(m, "exposure"));
        assertFalse(m.uniforms().containsKey("lobeCutoff"));
    }

    private static float value(Material m, String name) {
        return ((UniformValue.FloatValue) m.uniforms().get(name)).value();
    }
}
