package diffract.render;

import diffract.jrtr.textures.FloatTexture3D;
import diffract.jrtr.scenegraph.Material;
import diffract.jrtr.textures.Texture2D;
import diffract.optics.BakedGrid;
import diffract.optics.BrdfSettings;
import diffract.optics.numerics.Covariance2;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;
import diffract.optics.patches.ScanTiling;
import diffract.optics.windows.WindowPlacement;
import diffract.optics.patches.Direction;
import diffract.optics.spectra.PhaseCentres;
import diffract.optics.settings.PixelFilter;
import diffract.util.Reporter;

import java.util.Optional;

/**
 * {@link Material}s of the diffraction shaders: program, textures and the uniforms that mirror
 * {@link diffract.optics.DiffractionBrdf#create}'s parameters (extent, coherence window in texels, PQ replicas,
 * refractive index, wavelength interval; for the lobes method its quadrature, the pixel filter and the light).
 */
public final class DiffractionMaterials {
    private DiffractionMaterials() {
    }

    /**
     * A BRDF-map material (draw it on {@link diffract.jrtr.scenegraph.Shapes#fullScreenQuad()}); set {@code omegaI}
     * (and the lobes method's light) with {@link #setLight} and {@code mapSizePx} before drawing, and {@code lambdaNm}
     * when monochromatic.
     */
    public static Material brdfMap(DiffractionTextures textures, BrdfSettings settings, boolean monochromatic) {
        Material m = new Material(DiffractionShaders.program(settings, textures, DiffractionShaders.Target.BRDF_MAP,
                monochromatic, false));
        return mapWindow(common(m, textures, settings, false), settings);
    }

    /**
     * A BRDF-map material that outputs display sRGB of {@code exposure} x XYZ, for windows (8-bit framebuffers).
     * Set {@code omegaI} with {@link #setLight}, {@code mapSizePx}, and {@code mapOriginPx} (the map's lower-left
     * corner in the viewport, to centre it) before drawing.
     */
    public static Material brdfMapForDisplay(DiffractionTextures textures, BrdfSettings settings, float exposure,
                                             FrameOutput output) {
        Material m = new Material(DiffractionShaders.displayBrdfMapProgram(settings, textures, output));
        return mapWindow(common(m, textures, settings, false), settings).setFloat("exposure", exposure);
    }

    /**
     * A mesh material (003 Algorithms 2-4): display sRGB of exposure x XYZ, blended with {@code pigmentation}
     * (display-encoded sRGB, or null for pure structural colour) with diffuse weight w_d.
     */
    public static Material surface(DiffractionTextures textures, BrdfSettings settings, float exposure,
                                   Texture2D pigmentation, float diffuseWeight) {
        return surface(textures, settings, exposure, pigmentation, diffuseWeight, FrameOutput.DISPLAY);
    }

    /** As {@link #surface(DiffractionTextures, BrdfSettings, float, Texture2D, float)}, its pixels {@code output}. */
    public static Material surface(DiffractionTextures textures, BrdfSettings settings, float exposure,
                                   Texture2D pigmentation, float diffuseWeight, FrameOutput output) {
        Material m = new Material(DiffractionShaders.surfaceProgram(settings, textures, pigmentation != null,
                output));
        surfaceWindow(common(m, textures, settings, true), settings).setFloat("exposure", exposure);
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
                           float diffuseWeight, Stage stage, FrameOutput output, Reporter reporter) {
        Optional<BakedTable> table = DiffractionShaders.environmentTableNeeded(settings, stage)
                ? textures.tables().lobesTable(reporter) : Optional.empty();
        boolean sky = DiffractionShaders.skyTableNeeded(settings, textures, stage);
        Material m = new Material(DiffractionShaders.stagedSurfaceProgram(settings, textures, pigmentation != null,
                stage, table.isPresent(), sky, output));
        surfaceWindow(common(m, textures, settings, true), settings).setFloat("exposure", exposure);
        table.ifPresent(t -> filteredTable(m, t, t.texture(), settings));
        if (sky) {
            SkyTable spread = SkyTable.of(textures.baked(), stage.environment().lights(),
                    BakedDisc.heldSigmaRad(settings));
            m.setTexture("skyTable", spread.texture()).setVec2("skyTableSamples", spread.side(), spread.wSamples());
        }
        if (pigmentation != null) {
            m.setTexture("pigmentation", pigmentation).setFloat("diffuseWeight", diffuseWeight);
        }
        return m;
    }

    /**
     * The local window's centre on the scan (um) and the footprint's covariance (um^2) of a BRDF map
     * ({@code mapWindowCentreUm}, {@code mapFootprintUm2} in {@code diffraction_main.glsl}): a map has no surface
     * point, so its caller places the window; a material of another placement is returned unchanged.
     */
    public static Material placeMapWindow(Material brdfMap, BrdfSettings settings, double centreXUm, double centreYUm,
                                          Covariance2 footprintUm2) {
        if (settings.window().placement() != WindowPlacement.LOCAL) {
            return brdfMap;
        }
        return brdfMap.setVec2("mapWindowCentreUm", (float) centreXUm, (float) centreYUm)
                .setVec3("mapFootprintUm2", (float) footprintUm2.xx(), (float) footprintUm2.xy(),
                        (float) footprintUm2.yy());
    }

    /** A map's local window at the scan's origin, no footprint: the fixed window until it is placed. */
    private static Material mapWindow(Material m, BrdfSettings settings) {
        return placeMapWindow(m, settings, 0, 0, Covariance2.ZERO);
    }

    /** The scan's tiling of a surface's texture coordinates, for the local window ({@code setLocalWindow}). */
    private static Material surfaceWindow(Material m, BrdfSettings settings) {
        if (settings.window().placement() != WindowPlacement.LOCAL) {
            return m;
        }
        ScanTiling tiling = settings.window().tiling();
        if (!tiling.given()) {
            throw new InvalidSettingException(Quantity.SCAN_TILING, LOCAL_NEEDS_A_TILING);
        }
        return m.setVec2("skinUmPerTexcoord", (float) tiling.umPerTexcoordU(), (float) tiling.umPerTexcoordV())
                .setInt("scanColumnsAlongV", tiling.columnsAlongV() ? 1 : 0);
    }

    /** One line when a surface asks for the local window without saying how the scan lies on it. */
    public static final String LOCAL_NEEDS_A_TILING = "the local window needs to know how the scan lies on the skin:"
            + " give the micrometres of skin per unit of the mesh's texture coordinates";

    /**
     * The bake pass of a table of the method of {@code settings} per sample of {@code grid}
     * ({@link GpuMethod#bakeFragmentPath}); set {@code bakeW} per slice and draw on the full-screen quad into a
     * grid.uvSamples()^2 viewport.
     */
    static Material bake(DiffractionTextures textures, BrdfSettings settings, BakedGrid grid) {
        Material m = new Material(DiffractionShaders.bakeProgram(settings, textures));
        return common(m, textures, GpuMethods.of(settings.variant()).bakeSettings(settings), false)
                .setVec2("bakedSamples", grid.uvSamples(), grid.wSamples());
    }

    /**
     * omega_i of a BRDF map (towards the light, tangent frame) and, for the lobes method, the settings' light as its
     * (u, v) covariance at omega_i, split into its diagonal part and Gauss-Hermite shifts along the rest
     * ({@link Covariance2#diagonalPlusRankOne}), which every pixel of the map shares.
     */
    public static Material setLight(Material brdfMap, Direction wi, BrdfSettings settings) {
        brdfMap.setVec3("omegaI", (float) wi.x(), (float) wi.y(), (float) wi.z());
        GpuMethods.of(settings.variant()).setLight(brdfMap, wi, settings);
        return brdfMap;
    }

    /**
     * A display material shown at {@code exposure} from now on: its tone map and what its method draws for that
     * exposure ({@link GpuMethod#setExposure}; {@code settings} as asked, those the material was built with).
     */
    public static Material setExposure(Material display, BrdfSettings settings, double exposure) {
        display.setFloat("exposure", (float) exposure);
        GpuMethods.of(settings.variant()).setExposure(display, settings, exposure);
        return display;
    }

    /** 1 where surface pixels average over their footprint (PixelFilter.BOX), 0 where they take its centre. */
    static float pixelFootprintScale(BrdfSettings settings) {
        return settings.illumination().pixelFilter() == PixelFilter.BOX ? 1f : 0f;
    }

    /**
     * The lobes method's filtered table as {@code baked_table.glsl} reads it: its mip-mapped layers ({@code texture}),
     * its grid and the light it holds ({@link BakedDisc#heldSigmaRad}).
     */
    private static Material filteredTable(Material m, BakedTable table, FloatTexture3D texture, BrdfSettings settings) {
        return m.setTexture("bakedLayers", texture)
                .setVec2("bakedSamples", table.grid().uvSamples(), table.grid().wSamples())
                .setFloat("tableLightSigmaRad", (float) BakedDisc.heldSigmaRad(settings));
    }

    /**
     * The baked method's filtered table ({@link #filteredTable}) and, under a disc ({@code baked_disc.glsl}), the
     * disc's half-angle and either, on a surface under a wide disc, the table spread by the disc ({@link DiscTable})
     * or the running sums of its rows.
     */
    private static Material bakedFilteredTable(Material m, TableTextures tables, BrdfSettings settings,
                                               boolean surface) {
        filteredTable(m, tables.baked(), tables.texture(), settings);
        if (!BakedDisc.integrates(settings, true)) {
            return m;
        }
        double halfAngleRad = settings.illumination().light().halfAngleRad();
        m.setFloat("lightHalfAngleRad", (float) halfAngleRad);
        if (surface && DiscTable.applies(settings, tables.baked().grid())) {
            return m.setTexture("discTable", tables.discTable(halfAngleRad)).setFloat("discTableSide",
                    tables.discTableSide(halfAngleRad));
        }
        return m.setTexture("bakedRowSums", tables.rowSums());
    }

    /**
     * The uniforms of the variant's program, each set once, by the include that declares it: the method's own
     * ({@link GpuMethod}: its window, wavelengths and tables), the terms or the baked table, and the shared ones of
     * {@code diffraction_common.glsl}.
     */
    private static Material common(Material m, DiffractionTextures textures, BrdfSettings settings, boolean surface) {
        GpuMethods.of(settings.variant()).setUniforms(m, textures, settings);
        if (textures.baked() != null) {
            // the baked lookup reads its table only: the terms stay on the CPU (they were used by the bake)
            if (textures.baked().filtered()) {
                bakedFilteredTable(m, textures.tables(), settings, surface)
                        .setFloat("pixelFootprintScale", pixelFootprintScale(settings));
            } else {
                BakedGrid grid = textures.baked().grid();
                m.setTexture("bakedXyz", textures.tables().texture()).setVec2("bakedSamples", grid.uvSamples(),
                        grid.wSamples());
            }
        } else {
            m.setTexture("taylorTerms", textures.terms());
        }
        if (textures.baked() == null && textures.normalisedTerms()) {
            m.setTexture("termExtrema", textures.termExtrema());
        }
        PhaseCentres centres = textures.phaseCentres();
        if (centres != null) { // taylor_centred.glsl
            m.setFloat("centreSpacingPerUm", (float) centres.spacingPerUm()).setInt("centreCount", centres.centreCount());
        }
        return m.setFloat("taylorTolerance", (float) settings.taylor().tolerance())
                .setFloat("maxAbsHeightUm", (float) textures.maxAbsHeightUm())
                .setVec2("patchExtentUm", (float) textures.extentXUm(), (float) textures.extentYUm())
                .setFloat("refractiveIndex", (float) settings.illumination().refractiveIndex());
    }
}
