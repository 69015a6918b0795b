package diffract.app;

import diffract.jrtr.GlTestSupport;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.HeightField;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.LightPolicy;
import diffract.optics.settings.Quantity;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.Variant;
import diffract.precompute.TaylorTermComputer;
import diffract.render.GpuBrdfMap;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;

import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Which method takes a light of finite size is decided once ({@link LightPolicy}), and every place that asks gives
 * that answer in the same words: the CPU, the GPU, brdfmap (refusals) and a scene (a point light, with the notice);
 * the viewer's keys are held by ViewerModelTest.
 */
class LightPolicyTest {
    static final Set<Variant> TAKE_A_WIDE_LIGHT = Set.of(Variant.REFERENCE, Variant.LOBES, Variant.BAKED,
            Variant.RIGOROUS);
    static final HeightField PATCH = SyntheticPatches.blazed(2.5, 0.2, 20, 4, 16).meanSubtracted();

    static BrdfSettings settings(Variant v, double lightDeg) {
        return BrdfSettings.thesis(v).with(b -> b.highestOrder(8).lightSizeDeg(lightDeg));
    }

    @Test
    void aPointLightSuitsEveryMethodAndAWideOneOnlyThoseThatAverageOverIt() {
        for (Variant v : Variant.values()) {
            LightPolicy point = LightPolicy.of(settings(v, 0));
            assertTrue(point.accepted(), v.label());
            assertEquals(point.asked(), point.usable());
            LightPolicy wide = LightPolicy.of(settings(v, 2));
            assertEquals(TAKE_A_WIDE_LIGHT.contains(v), wide.accepted(), v.label());
            if (!wide.accepted()) {
                assertEquals(0, wide.usable().illumination().light().angularDiameterDeg(), v.label());
                assertEquals(v, wide.usable().variant());
                assertEquals(v.label() + " samples the light at its centre only: a light of 2 degrees (disc) needs "
                        + "a method that averages over it, reference, baked, lobes or rigorous (or a point light, 0 degrees)",
                        wide.reason().get());
                assertEquals(v.label() + " samples the light at its centre: the 2-degree light is drawn as a point "
                        + "light (baked and lobes filter by its size)", wide.notice().get());
                InvalidSettingException e = assertThrows(InvalidSettingException.class, wide::requireAccepted);
                assertEquals(Quantity.LIGHT_SIZE, e.quantity());
            } else {
                assertEquals(wide.asked(), wide.usable());
                assertTrue(wide.notice().isEmpty());
            }
        }
    }

    @Test
    void theCpuAndBrdfmapRefuseWithThePolicysReason() {
        TaylorTerms terms = TaylorTermComputer.compute(PATCH, 8, Reporter.SILENT);
        String reason = LightPolicy.of(settings(Variant.NMM, 2)).reason().orElseThrow();
        InvalidSettingException cpu = assertThrows(InvalidSettingException.class,
                () -> DiffractionBrdf.create(settings(Variant.NMM, 2), PATCH, terms));
        assertEquals(reason, cpu.getMessage());
        Object[] cli = CliTest.run("brdfmap", "--synthetic", "blazed", "--theta-i", "30", "--variant", "nmm",
                "--light-size-deg", "2", "--size", "8", "-o", "target/never-written.png");
        assertEquals(2, cli[0]);
        assertTrue(((String) cli[2]).contains(reason), (String) cli[2]);
        // the methods that take it do not refuse
        DiffractionBrdf.create(settings(Variant.LOBES, 2), PATCH, terms);
        DiffractionBrdf.create(settings(Variant.REFERENCE, 2), PATCH, null);
    }

    @Test
    void theGpuRefusesWithThePolicysReason() {
        GlTestSupport.assumeOffscreenGl();
        TaylorTerms terms = TaylorTermComputer.compute(PATCH, 8, Reporter.SILENT);
        String reason = LightPolicy.of(settings(Variant.PQ, 2)).reason().orElseThrow();
        InvalidSettingException gpu = assertThrows(InvalidSettingException.class,
                () -> new GpuBrdfMap(terms, settings(Variant.PQ, 2)).close());
        assertEquals(reason, gpu.getMessage());
        assertFalse(reason.isBlank());
    }
}
