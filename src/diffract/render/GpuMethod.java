package diffract.render;

import diffract.jrtr.scenegraph.Material;
import diffract.optics.BrdfSettings;
import diffract.optics.patches.Direction;

/**
 * A diffraction method's GPU side: the uniforms and textures its fragment shader declares beyond the ones every
 * diffraction shader shares ({@link DiffractionMaterials}: the patch, the terms or the baked table, the refractive
 * index), set from the settings and the patch's textures, and what it reads of a BRDF map's light. One class per
 * method, found by {@link GpuMethods}; its program is {@code shaders/diffraction/<label>.frag}
 * ({@link DiffractionShaders}).
 */
public interface GpuMethod {
    /** Its own uniforms and textures, each once. */
    void setUniforms(Material m, DiffractionTextures textures, BrdfSettings settings);

    /** The light of a BRDF map at omega_i (towards the light), beyond {@code omegaI}: none unless it reads more. */
    default void setLight(Material brdfMap, Direction wi, BrdfSettings settings) {
    }

    /**
     * What the picture's exposure changes in its uniforms beyond the tone map, for settings as asked (not already
     * {@link BrdfSettings#shownAt shown} at an exposure): nothing unless its quadrature drops what the display cannot
     * show.
     */
    default void setExposure(Material m, BrdfSettings settings, double exposure) {
    }

    /**
     * Defines its program takes beyond the shared ones, from the settings, for a BRDF map's program or a surface's:
     * none unless it compiles variants of its code.
     */
    default void addDefines(java.util.Map<String, String> defines, BrdfSettings settings, boolean brdfMap) {
    }

    /**
     * Whether its fragments write alpha 0 where the GL ended their loops before their work was done
     * ({@link ShortPixels}), so that a reader of its pictures can count the pixels left short.
     */
    default boolean reportsShortPixels() {
        return false;
    }

    /**
     * Whether a staged surface of this method reads the lobes method's baked table over the footprints of environment
     * lights wider than it sums ({@link DiffractionShaders#TABLE_BEYOND_SIGMA_RAD}).
     */
    default boolean tablesWideEnvironmentLights() {
        return false;
    }

    /** Whether a staged surface of this method reads environment lights from tables spread by each light ({@link SkyTable}). */
    default boolean readsSkyTables() {
        return false;
    }

    /**
     * The fragment shader of its bake pass, which writes its spectral XYZ per sample of a baked table
     * ({@link BakedTable}) for the methods a table can hold ({@link diffract.optics.Variant#bakeable}); null for the
     * others.
     */
    default String bakeFragmentPath() {
        return null;
    }

    /** Defines its bake pass takes beyond those of its BRDF map's program with {@link #bakeSettings}. */
    default void addBakeDefines(java.util.Map<String, String> defines, BrdfSettings settings) {
    }

    /**
     * The settings its bake pass draws with: {@code settings} unless a table's sample stands for more than a point
     * (the lobes method averages every sample over its cell).
     */
    default BrdfSettings bakeSettings(BrdfSettings settings) {
        return settings;
    }

    /** The Gaussian coherence window in texels per axis ({@code spectrum_gaussian.glsl}'s sigmaTexels). */
    static void gaussianWindow(Material m, DiffractionTextures textures, BrdfSettings settings) {
        m.setVec2("sigmaTexels", (float) settings.coherenceWindow().sigmaTexels(textures.extentXUm()),
                (float) settings.coherenceWindow().sigmaTexels(textures.extentYUm()));
    }
}
