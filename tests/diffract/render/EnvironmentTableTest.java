package diffract.render;

import diffract.jrtr.GlTestSupport;
import diffract.optics.illumination.LightSource;
import diffract.optics.Variant;
import diffract.scene.Fabricator;
import diffract.scene.SceneSetup;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Environment lights wider than the lobes method takes read the lobes method's baked table on a staged surface
 * (surface_stage.glsl, ENVIRONMENT_TABLE): summed lobe by lobe, a sky light tens of degrees wide reaches thousands of
 * lobes per fragment, and on llvmpipe the shader's loops stop silently after 65535 iterations, leaving blocks of
 * fragments dark.
 */
class EnvironmentTableTest {
    @Test
    void onlyTheLobesMethodUnderLightsWiderThanItTakesReadsTheTable() {
        assertTrue(DiffractionShaders.environmentTableNeeded(Variant.LOBES, 58));
        assertTrue(DiffractionShaders.environmentTableNeeded(Variant.LOBES, LightSource.MAX_DIAMETER_DEG + 0.1));
        assertFalse(DiffractionShaders.environmentTableNeeded(Variant.LOBES, LightSource.MAX_DIAMETER_DEG));
        assertFalse(DiffractionShaders.environmentTableNeeded(Variant.LOBES, 0));
        assertFalse(DiffractionShaders.environmentTableNeeded(Variant.BAKED, 58), "the baked variant reads it anyway");
        assertFalse(DiffractionShaders.environmentTableNeeded(Variant.FLSS, 58), "FLSS sees the lights' directions");
        assertEquals(Math.toRadians(LightSource.MAX_DIAMETER_DEG) / 4, DiffractionShaders.TABLE_BEYOND_SIGMA_RAD, 1e-15);
    }

    /**
     * The Xenopeltis scene (8 sky lights, most of them wider than 20 degrees): the lobes method's picture and the
     * baked table's read the same table for the sky and differ in the key light's glints only, so nowhere is the
     * lobes method's picture much darker than the table's (its dark blocks were).
     */
    @Test
    @Tag("gl")
    void aWideSkyLightsTheLobesMethodsSurfaceAsTheTableDoes() {
        GlTestSupport.assumeOffscreenGl();
        SceneSetup scene = Fabricator.fabricate(Path.of("assets", "scenes", "snake-xenopeltis.json"),
                Reporter.SILENT);
        assertTrue(scene.stage().widestEnvironmentLightDeg() > LightSource.MAX_DIAMETER_DEG,
                "the scene's sky has lights wider than the lobes method takes: "
                        + scene.stage().widestEnvironmentLightDeg());
        SceneSetup lobes = scene.withSettings(scene.settings().with(b -> b.variant(Variant.LOBES)));
        SceneSetup baked = scene.withSettings(scene.settings().with(b -> b.variant(Variant.BAKED)));
        float[] a = StagedSurfaceTest.render(lobes);
        float[] b = StagedSurfaceTest.render(baked);
        int lit = 0;
        int darker = 0;
        double difference = 0;
        for (int p = 0; p < a.length / 3; p++) {
            double ya = luminance(a, p);
            double yb = luminance(b, p);
            if (yb > 0.1) {
                lit++;
                difference += Math.abs(ya - yb);
                if (ya < 0.5 * yb) {
                    darker++;
                }
            }
        }
        TestReport.printf(EnvironmentTableTest.class, Locale.ROOT,
                "%d lit pixels, %d at less than half the table's luminance, mean |difference| %.4f%n", lit, darker,
                difference / lit);
        assertTrue(lit > 500, "the snake and the ground are lit: " + lit + " pixels");
        assertTrue(darker <= 0.01 * lit, darker + " of " + lit + " pixels far darker than the table's");
        assertTrue(difference / lit < 0.03, "mean luminance difference " + difference / lit);
    }

    private static double luminance(float[] rgb, int p) {
        return 0.2126 * rgb[3 * p] + 0.7152 * rgb[3 * p + 1] + 0.0722 * rgb[3 * p + 2];
    }
}
