package diffract.render;

import diffract.jrtr.Material;
import diffract.jrtr.Texture2D;
import diffract.optics.BakedGrid;
import diffract.optics.BrdfSettings;
import diffract.optics.CoherenceWindow;
import diffract.optics.Direction;
import diffract.optics.PhaseCentres;
import diffract.optics.Variant;

/**
 * {@link Material}s of the diffraction shaders: program, textures and the uniforms that mirror
 * {@link diffract.optics.DiffractionBrdf#create}'s parameters (extent, coherence window in texels, PQ replicas,
 * refractive index, wavelength interval).
 */
public final class DiffractionMaterials {
    private DiffractionMaterials() {
    }

    /**
     * A BRDF-map material (draw it on {@link diffract.jrtr.Shapes#fullScreenQuad()}); set {@code omegaI} with
     * {@link #setLight} and {@code mapSizePx} before drawing, and {@code lambdaNm} when monochromatic.
     */
    public static Material brdfMap(DiffractionTextures textures, BrdfSettings settings, boolean monochromatic) {
        Material m = new Material(DiffractionShaders.program(settings, textures, DiffractionShaders.Target.BRDF_MAP,
                monochromatic, false));
        return common(m, textures, settings);
    }

    /**
     * A BRDF-map material that outputs display sRGB of {@code exposure} x XYZ, for windows (8-bit framebuffers).
     * Set {@code omegaI} with {@link #setLight}, {@code mapSizePx}, and {@code mapOriginPx} (the map's lower-left
     * corner in the viewport, to centre it) before drawing.
     */
    public static Material brdfMapForDisplay(DiffractionTextures textures, BrdfSettings settings, float exposure) {
        Material m = new Material(DiffractionShaders.displayBrdfMapProgram(settings, textures));
        return common(m, textures, settings).setFloat("exposure", exposure);
    }

    /**
     * A mesh material (003 Algorithms 2-4): display sRGB of exposure x XYZ, blended with {@code pigmentation}
     * (display-encoded sRGB, or null for pure structural colour) with diffuse weight w_d.
     */
    public static Material surface(DiffractionTextures textures, BrdfSettings settings, float exposure,
                                   Texture2D pigmentation, float diffuseWeight) {
        Material m = new Material(DiffractionShaders.program(settings, textures, DiffractionShaders.Target.SURFACE,
                false, pigmentation != null));
        common(m, textures, settings).setFloat("exposure", exposure);
        if (pigmentation != null) {
            m.setTexture("pigmentation", pigmentation).setFloat("diffuseWeight", diffuseWeight);
        }
        return m;
    }

    /**
     * A mesh material on a {@link Stage} (set its textures and per-frame uniforms with {@link StageResources}):
     * the same constants as {@link #surface}, the program compiled with the stage's defines.
     */
    static Material staged(DiffractionTextures textures, BrdfSettings settings, float exposure, Texture2D pigmentation,
                           float diffuseWeight, Stage stage) {
        Material m = new Material(DiffractionShaders.stagedSurfaceProgram(settings, textures, pigmentation != null,
                stage));
        common(m, textures, settings).setFloat("exposure", exposure);
        if (pigmentation != null) {
            m.setTexture("pigmentation", pigmentation).setFloat("diffuseWeight", diffuseWeight);
        }
        return m;
    }

    /**
     * The bake pass of a BAKED table: FLSS of {@code flssSettings} per sample of {@code grid}; set {@code bakeW} per
     * slice and draw on the full-screen quad into a grid.uvSamples()^2 viewport.
     */
    static Material bake(DiffractionTextures textures, BrdfSettings flssSettings, BakedGrid grid) {
        Material m = new Material(DiffractionShaders.bakeProgram(flssSettings, textures));
        return common(m, textures, flssSettings).setVec2("bakedSamples", grid.uvSamples(), grid.wSamples());
    }

    /** omega_i of a BRDF map (towards the light, tangent frame). */
    public static Material setLight(Material brdfMap, Direction wi) {
        return brdfMap.setVec3("omegaI", (float) wi.x(), (float) wi.y(), (float) wi.z());
    }

    /**
     * The uniforms of the variant's program, each set once, by the include that declares it: the window
     * ({@code spectrum_gaussian.glsl} or PQ's {@code spectrum_sinc.glsl}), the wavelengths
     * ({@code wavelengths_uniform.glsl}, and NMM's {@code wavelengths_nmm.glsl} over it), the terms or the baked table, and
     * the shared ones of {@code diffraction_common.glsl}.
     */
    private static Material common(Material m, DiffractionTextures textures, BrdfSettings settings) {
        double extentX = textures.extentXUm();
        double extentY = textures.extentYUm();
        CoherenceWindow window = settings.coherenceWindow();
        if (textures.baked() != null) {
            // the baked lookup reads its table only: the terms stay on the CPU (they were used by the bake)
            BakedGrid grid = textures.baked().grid();
            m.setTexture("bakedXyz", textures.bakedTexture()).setVec2("bakedSamples", grid.uvSamples(), grid.wSamples());
        } else {
            m.setTexture("taylorTerms", textures.terms());
        }
        m.setTexture("uniformNodeTable", textures.uniformNodeTable()); // NMM's fallback grid too
        if (settings.variant() == Variant.NMM) {
            m.setTexture("spectralTable", textures.spectralTable())
                    .setFloat("spectralTableFirstNm", (float) textures.spectralTableFirstNm())
                    .setFloat("lambdaMinNm", (float) settings.spectral().lambdaMinNm())
                    .setFloat("lambdaMaxNm", (float) settings.spectral().lambdaMaxNm());
        }
        if (textures.baked() == null && textures.normalisedTerms()) {
            m.setTexture("termExtrema", textures.termExtrema());
        }
        if (settings.variant() == Variant.PQ) {
            // the replica counts of DiffractionBrdf.create(PQ)
            m.setVec2("pqReplicas", settings.window().replicas(window, extentX), settings.window().replicas(window, extentY));
        } else {
            m.setVec2("sigmaTexels", (float) window.sigmaTexels(extentX), (float) window.sigmaTexels(extentY));
        }
        PhaseCentres centres = textures.phaseCentres();
        if (centres != null) { // taylor_centred.glsl
            m.setFloat("centreSpacingPerUm", (float) centres.spacingPerUm()).setInt("centreCount", centres.centreCount());
        }
        return m.setFloat("taylorTolerance", (float) settings.taylor().tolerance())
                .setFloat("maxAbsHeightUm", (float) textures.maxAbsHeightUm())
                .setVec2("patchExtentUm", (float) extentX, (float) extentY)
                .setFloat("refractiveIndex", (float) settings.illumination().refractiveIndex());
    }
}
