package diffract.render;

import diffract.jrtr.scenegraph.Material;
import diffract.jrtr.shaders.UniformValue;
import diffract.optics.BrdfSettings;
import diffract.optics.LobeQuadrature;
import diffract.optics.Variant;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

/**
 * A display material shown at a new exposure (the viewer's exposure keys): the tone map takes it, and the lobes
 * method's cutoff follows it as {@link LobeQuadrature#shownAt} scales it, so that a brighter picture keeps the dim
 * lobes it now shows, from the cutoff as asked whatever exposure the settings were drawn for; a method without a
 * cutoff gets the tone map alone.
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

    /** A scene's settings are drawn for its exposure before the viewer shows them at it: the cutoff is scaled once. */
    @Test
    void settingsAlreadyShownAtTheExposureKeepTheirCutoff() {
        BrdfSettings lobes = BrdfSettings.thesis(Variant.LOBES);
        double exposure = 1353.76;
        BrdfSettings drawn = lobes.shownAt(exposure);
        Material m = new Material(null);
        DiffractionMaterials.setExposure(m, drawn, exposure);
        double once = LobeQuadrature.DEFAULT_CUTOFF * LobeQuadrature.CUTOFF_EXPOSURE / exposure;
        assertEquals(once, value(m, "lobeCutoff"), 1e-6 * once);
        DiffractionMaterials.setExposure(m, drawn, 3);
        assertEquals((float) LobeQuadrature.DEFAULT_CUTOFF, value(m, "lobeCutoff"), "dim again: the cutoff as asked");
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
