package diffract.render;

import diffract.colour.Srgb;
import diffract.jrtr.scenegraph.ShaderProgram;
import diffract.optics.BrdfSettings;
import diffract.optics.Variant;
import diffract.util.UserInputException;
import org.junit.jupiter.api.Test;

import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Shader selection, defines and preprocessing, without a GL context. */
class DiffractionShadersTest {
    @Test
    void everyVariantAndTargetPreprocessesWithItsDefines() {
        for (Variant variant : new Variant[] {Variant.FLSS, Variant.NMM, Variant.PQ}) {
            BrdfSettings settings = BrdfSettings.thesis(variant);
            ShaderProgram map = DiffractionShaders.program(settings, DiffractionShaders.Target.BRDF_MAP, false, false);
            String fragment = map.fragmentShader().source().text();
            assertTrue(fragment.startsWith("#version 330 core"), fragment.substring(0, 40));
            assertTrue(fragment.contains("#define TAYLOR_HIGHEST_ORDER 30"));
            assertTrue(fragment.contains("#define WINDOW_RADIUS 1"));
            assertTrue(fragment.contains("#define BRDF_MAP 1"));
            assertTrue(fragment.contains("float gainTimesShadowing("), "shared include expanded");
            assertEquals(variant == Variant.PQ, fragment.contains("normalisedDirichlet"), variant.toString());
            assertEquals(variant == Variant.NMM, fragment.contains("nmmSpectralXyz"), variant.toString());
            assertEquals(1, count(fragment, "float taylorCoefficients") + count(fragment, "void taylorCoefficients"),
                    "the shared code appears once");
            ShaderProgram surface = DiffractionShaders.program(settings, DiffractionShaders.Target.SURFACE, false, true);
            assertTrue(surface.fragmentShader().source().text().contains("#define PIGMENTATION 1"));
            // the engine's light arrays sized from RenderContext.MAX_LIGHTS, not by hand
            assertTrue(surface.vertexShader().source().text().contains("#define ENGINE_MAX_LIGHTS "
                    + diffract.jrtr.scenegraph.RenderContext.MAX_LIGHTS));
            assertTrue(surface.vertexShader().source().text().contains("lightDirection[ENGINE_MAX_LIGHTS]"));
            ShaderProgram mono = DiffractionShaders.program(settings, DiffractionShaders.Target.BRDF_MAP, true, false);
            assertTrue(mono.fragmentShader().source().text().contains("#define MONOCHROMATIC 1"));
        }
    }

    @Test
    void theReferenceIsRefusedWithOneLine() {
        UserInputException e = assertThrows(UserInputException.class,
                () -> DiffractionShaders.fragmentPath(Variant.REFERENCE));
        assertFalse(e.getMessage().contains("\n"));
        assertTrue(e.getMessage().contains("CPU only"), e.getMessage());
    }

    @Test
    void switchesBelongToTheirTarget() {
        BrdfSettings s = BrdfSettings.thesis(Variant.FLSS);
        assertThrows(IllegalArgumentException.class,
                () -> DiffractionShaders.defines(s, DiffractionShaders.Target.SURFACE, true, false));
        assertThrows(IllegalArgumentException.class,
                () -> DiffractionShaders.defines(s, DiffractionShaders.Target.BRDF_MAP, false, true));
        Map<String, String> d = DiffractionShaders.defines(s.with(b -> b.highestOrder(12)).with(b -> b.windowRadius(2)),
                DiffractionShaders.Target.BRDF_MAP, false, false);
        assertEquals("12", d.get("TAYLOR_HIGHEST_ORDER"));
        assertEquals("2", d.get("WINDOW_RADIUS"));
        assertEquals("1024", d.get("NMM_MAX_NODES"));
        assertEquals("2", d.get("WINDOW_RADIUS_X"));
        assertEquals("2", d.get("WINDOW_RADIUS_Y"));
        // Per-axis radii (automatic ones need the patch, so the settings-only overload refuses them)
        Map<String, String> perAxis = DiffractionShaders.defines(s, 9, new diffract.optics.windows.WindowRadii(2, 0),
                DiffractionShaders.Target.BRDF_MAP, false, false);
        assertEquals("9", perAxis.get("TAYLOR_HIGHEST_ORDER"));
        assertEquals("2", perAxis.get("WINDOW_RADIUS"));
        assertEquals("2", perAxis.get("WINDOW_RADIUS_X"));
        assertEquals("0", perAxis.get("WINDOW_RADIUS_Y"));
        assertThrows(IllegalArgumentException.class, () -> DiffractionShaders.defines(
                s.with(b -> b.automaticWindowRadius(true)), DiffractionShaders.Target.BRDF_MAP, false, false));
    }

    /** GLSL's mat3(a, b, c, ...) fills column 0 first: the constructor must list Srgb's matrix column by column. */
    @Test
    void xyzToSrgbMatrixIsWrittenColumnMajor() {
        double[][] m = Srgb.xyzToLinearMatrix();
        String glsl = DiffractionShaders.glslMat3(m);
        String[] entries = glsl.substring(5, glsl.length() - 1).split(", ");
        assertEquals(9, entries.length);
        for (int col = 0; col < 3; col++) {
            for (int row = 0; row < 3; row++) {
                assertEquals((float) m[row][col], Float.parseFloat(entries[3 * col + row]), 0.0,
                        "entry (" + row + ", " + col + ")");
            }
        }
    }

    private static int count(String text, String needle) {
        int n = 0;
        for (int i = text.indexOf(needle); i >= 0; i = text.indexOf(needle, i + 1)) {
            n++;
        }
        return n;
    }
}
