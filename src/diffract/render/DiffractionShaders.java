package diffract.render;

import diffract.colour.Srgb;
import diffract.jrtr.scenegraph.ShaderProgram;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.illumination.DiscFootprint;
import diffract.optics.LobeSpectrum;
import diffract.optics.Methods;
import diffract.optics.windows.WindowPlacement;
import diffract.optics.settings.GainModel;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.illumination.LightSource;
import diffract.optics.spectra.PhaseCentres;
import diffract.optics.settings.Quantity;
import diffract.optics.Variant;
import diffract.optics.windows.WindowRadii;

import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/**
 * The GLSL programs of {@code shaders/diffraction/}: one thin fragment shader per variant ({@code flss.frag},
 * {@code nmm.frag}, {@code pq.frag}, {@code baked.frag}, {@code lobes.frag}) over shared includes, specialised by
 * compile-time {@code #define}s.
 *
 * <p>Texture blending on meshes (003 Algorithm 4) is printed garbled in the thesis (section 1.4.2: alpha = |F| is
 * called "the fraction which goes into the skin", and c_texture and c_pigmentation appear without a definition).
 * We implement it as the physics it describes, in linear light: the interface reflects the fraction
 * alpha = clamp(F, 0, 1) (the structural colour, whose gain factor already holds the Fresnel term), 1 - alpha enters
 * the skin and is scattered by the pigment diffusely (Lambert, times cos theta_i), and a constant weight w_d mixes
 * the pigment in as ambient light: c_total = (1 - w_d)(c_diffraction + (1 - alpha) cos(theta_i) c_pigment)
 * + w_d c_pigment (see {@code blendPigmentation} in {@code diffraction_common.glsl}).
 */
public final class DiffractionShaders {
    /** Where the fragment shader's directions come from. */
    public enum Target {
        /** A full-screen quad; omega_r from the map pixel (BrdfMap's convention), output linear XYZ. */
        BRDF_MAP,
        /** A mesh through surface.vert (003 Algorithm 2); output display sRGB. */
        SURFACE
    }

    /** Why a method without a shader (the exact reference) cannot be asked of the GPU, and what can. */
    public static String cpuOnly(Variant variant) {
        return "the " + variant.label() + " variant runs on the CPU only; the GPU renders "
                + Methods.listed(Variant::runsOnGpu, "and");
    }

    private DiffractionShaders() {
    }

    /** The variant's fragment shader under {@code /shaders}; the reference has none. */
    public static String fragmentPath(Variant variant) {
        if (!variant.runsOnGpu()) {
            throw new InvalidSettingException(Quantity.VARIANT, cpuOnly(variant));
        }
        return "diffraction/" + variant.label() + ".frag";
    }

    public static String vertexPath(Target target) {
        return target == Target.BRDF_MAP ? "diffraction/brdfmap.vert" : "diffraction/surface.vert";
    }

    /**
     * The compile-time constants: Taylor order, window radius, NMM node budget, the XYZ to linear sRGB matrix,
     * the target, the Fresnel model ({@code FRESNEL_THESIS} for the thesis' squared factor) and the optional
     * switches.
     */
    public static Map<String, String> defines(BrdfSettings settings, Target target, boolean monochromatic,
                                              boolean pigmentation) {
        if (settings.window().automatic()) {
            throw new IllegalArgumentException("an automatic window radius needs the patch: use defines(settings, "
                    + "highestOrder, radii, ...)");
        }
        int r = settings.window().radius();
        return defines(settings, settings.taylor().highestOrder(), new WindowRadii(r, r), target, monochromatic,
                pigmentation);
    }

    /**
     * As above with the Taylor order and window radii a patch actually needs ({@link DiffractionTextures#highestOrder},
     * {@link DiffractionTextures#windowRadii}): WINDOW_RADIUS_X and _Y per axis, WINDOW_RADIUS their maximum.
     */
    public static Map<String, String> defines(BrdfSettings settings, int highestOrder, WindowRadii radii, Target target,
                                              boolean monochromatic, boolean pigmentation) {
        return defines(settings, highestOrder, radii, null, target, monochromatic, pigmentation);
    }

    /**
     * As above; with {@code phaseCentres} (not null) the shader expands around the nearest phase centre
     * ({@code PHASE_CENTRED}, {@code taylor_centred.glsl}) and {@code highestOrder} is the centres' order.
     */
    public static Map<String, String> defines(BrdfSettings settings, int highestOrder, WindowRadii radii,
                                              PhaseCentres phaseCentres, Target target, boolean monochromatic,
                                              boolean pigmentation) {
        Map<String, String> defines = new TreeMap<>();
        defines.put("TAYLOR_HIGHEST_ORDER", Integer.toString(highestOrder));
        if (phaseCentres != null) {
            defines.put("PHASE_CENTRED", "1");
        }
        defines.put("WINDOW_RADIUS", Integer.toString(Math.max(radii.x(), radii.y())));
        defines.put("WINDOW_RADIUS_X", Integer.toString(radii.x()));
        defines.put("WINDOW_RADIUS_Y", Integer.toString(radii.y()));
        if (settings.window().placement() == WindowPlacement.FIXED) {
            defines.put("WINDOW_FIXED", "1");
        } else if (settings.window().placement() == WindowPlacement.LOCAL) {
            defines.put("WINDOW_LOCAL", "1");
        }
        defines.put("NMM_MAX_NODES", Integer.toString(DiffractionBrdf.NMM_MAX_NODES));
        defines.put("LIGHT_NODES_MAX", Integer.toString(LobesGpu.LIGHT_NODES_MAX));
        // the disc's constants, from DiscFootprint (lobes_footprint.glsl)
        defines.put("DISC_RING_SAMPLES", Integer.toString(DiscFootprint.RING_SAMPLES));
        defines.put("DISC_GAUSSIAN_BELOW", Float.toString((float) DiscFootprint.GAUSSIAN_BELOW));
        defines.put("DISC_EDGE_ABOVE", Float.toString((float) DiscFootprint.EDGE_ABOVE));
        // the texel sums' guard on their wavelength nodes (lobes_sum.glsl)
        defines.put("MAX_SUM_NODES", Integer.toString(LobeSpectrum.MAX_SUM_NODES));
        // the texels per side of the weight table's blocks of bounds (lobes_spectrum.glsl)
        defines.put("LOBE_BLOCK", Integer.toString(diffract.optics.lobes.LobeWeightTable.BLOCK));
        defines.put("LOBE_ROWS_FACTOR", Integer.toString(LobeSpectrum.ROWS_FACTOR));
        defines.put("WIDEST_HAT_NM", Integer.toString(diffract.colour.HatFilteredSpectrum.WIDEST_HAT_NM));
        defines.put("XYZ_TO_LINEAR_SRGB", glslMat3(Srgb.xyzToLinearMatrix()));
        defines.put(target.name(), "1");
        if (settings.illumination().gain() == GainModel.RAYLEIGH_RICE) {
            defines.put("GAIN_RAYLEIGH_RICE", "1");
        }
        if (settings.illumination().gain() == GainModel.THESIS) {
            defines.put("FRESNEL_THESIS", "1");
        }
        if (monochromatic) {
            if (target != Target.BRDF_MAP) {
                throw new IllegalArgumentException("monochromatic output exists for BRDF maps only");
            }
            defines.put("MONOCHROMATIC", "1");
        }
        if (pigmentation) {
            if (target != Target.SURFACE) {
                throw new IllegalArgumentException("pigmentation blending exists for surfaces only");
            }
            defines.put("PIGMENTATION", "1");
        }
        return defines;
    }

    /** The program of a variant for a target (compiled on first use in a GL context). */
    public static ShaderProgram program(BrdfSettings settings, Target target, boolean monochromatic,
                                        boolean pigmentation) {
        return ShaderProgram.fromClasspath(vertexPath(target), fragmentPath(settings.variant()),
                defines(settings, target, monochromatic, pigmentation));
    }

    /**
     * The program for the order, radii and expansion of these textures (what DiffractionMaterials uses): plain, or
     * phase-centred when the textures hold phase-centred terms.
     */
    public static ShaderProgram program(BrdfSettings settings, DiffractionTextures textures, Target target,
                                        boolean monochromatic, boolean pigmentation) {
        return ShaderProgram.fromClasspath(vertexPath(target), fragmentPath(settings.variant()),
                definesFor(settings, textures, target, monochromatic, pigmentation));
    }

    /**
     * sigma_a of the widest light the lobes method sums on a staged surface (LightSource's largest diameter, where
     * it is measured against the reference): a wider environment light reaches thousands of lobes per fragment (on
     * llvmpipe past the 65535 loop iterations one shader invocation may run, after which its loops stop silently), and
     * reads the lobes method's baked table over its footprint instead.
     */
    public static final double TABLE_BEYOND_SIGMA_RAD = LightSource.sigmaRadOf(LightSource.MAX_DIAMETER_DEG);

    /** Whether a staged surface of these settings reads the lobes method's table for its widest environment lights. */
    public static boolean environmentTableNeeded(BrdfSettings settings, Stage stage) {
        return environmentTableNeeded(settings.variant(), stage.widestEnvironmentLightDeg());
    }

    /** As above, for the variant and the angular diameter of the widest environment light (degrees, 0: none). */
    static boolean environmentTableNeeded(Variant variant, double widestEnvironmentLightDeg) {
        return GpuMethods.of(variant).tablesWideEnvironmentLights()
                && LightSource.sigmaRadOf(widestEnvironmentLightDeg) > TABLE_BEYOND_SIGMA_RAD;
    }

    /**
     * Whether a staged surface of the baked variant reads its environment lights from tables spread in advance by each
     * light ({@link SkyTable}): a filtered table under an environment.
     */
    public static boolean skyTableNeeded(BrdfSettings settings, DiffractionTextures textures, Stage stage) {
        return GpuMethods.of(settings.variant()).readsSkyTables() && textures.baked() != null
                && textures.baked().filtered()
                && stage.environment() != null && !stage.environment().lights().isEmpty()
                && stage.glossyAlpha() == null;
    }

    /**
     * The surface program on a {@link Stage}: the same BRDF, evaluated per fragment in each scale's frame for the key
     * and environment lights, tone mapped ({@code surface_stage.glsl}, switched on by the stage's defines);
     * with {@code environmentTable} the lobes method's wide environment lights read its table (ENVIRONMENT_TABLE),
     * with {@code skyTable} the baked variant's read their spread tables (SKY_TABLE).
     */
    public static ShaderProgram stagedSurfaceProgram(BrdfSettings settings, DiffractionTextures textures,
                                                     boolean pigmentation, Stage stage, boolean environmentTable,
                                                     boolean skyTable, FrameOutput output) {
        Map<String, String> defines = definesFor(settings, textures, Target.SURFACE, false, pigmentation);
        defines.putAll(stage.defines());
        output.addDefines(defines);
        if (environmentTable) {
            defines.put("ENVIRONMENT_TABLE", "1");
            defines.put("TABLE_BEYOND_SIGMA_RAD", Float.toString((float) TABLE_BEYOND_SIGMA_RAD));
        }
        if (skyTable) {
            defines.put("SKY_TABLE", "1");
        }
        return ShaderProgram.fromClasspath(vertexPath(Target.SURFACE), fragmentPath(settings.variant()), defines);
    }

    /**
     * Defines for these textures: their order, radii, expansion, for 8-bit terms {@code TERMS_UNORM8}, and for a
     * baked table of the lobes method {@code BAKED_FILTERED}.
     */
    private static Map<String, String> definesFor(BrdfSettings settings, DiffractionTextures textures, Target target,
                                                  boolean monochromatic, boolean pigmentation) {
        Map<String, String> defines = defines(settings, textures.highestOrder(), textures.windowRadii(),
                textures.phaseCentres(), target, monochromatic, pigmentation);
        boolean mapPixel = target == Target.BRDF_MAP;
        if (textures.normalisedTerms()) {
            // the term lookup de-normalises 8-bit [0, 1] terms with the per-term extrema (NormalisedTerms)
            defines.put("TERMS_UNORM8", "1");
        }
        if (textures.baked() != null && textures.baked().filtered()) {
            // the table holds cell- and light-averaged samples with mip levels: look up over the pixel's footprint
            defines.put("BAKED_FILTERED", "1");
            if (BakedDisc.integrates(settings, true)) {
                // the lookup integrates the disc over the running sums of the table's rows (baked_disc.glsl)
                defines.put("BAKED_DISC", "1");
                defines.put("LIGHT_DISC", "1");
                defines.put("DISC_ROWS_MAX", Integer.toString(BakedDisc.ROWS_MAX));
                defines.put("DISC_MIN_ROWS", Integer.toString(BakedDisc.MIN_ROWS));
                defines.put("DISC_FINE_ROWS_MAX", Integer.toString(BakedDisc.FINE_ROWS_MAX));
                defines.put("DISC_PIECES_MAX", Integer.toString(BakedDisc.PIECES_MAX));
                defines.put("DISC_TABLE_GAUSSIAN_BELOW", Float.toString((float) BakedDisc.gaussianBelow(mapPixel)));
                defines.put("DISC_TABLE_EDGE_ABOVE", Float.toString((float) BakedDisc.edgeAbove(mapPixel)));
                defines.put("DISC_TABLE_BOX_BELOW", Float.toString((float) BakedDisc.BOX_BELOW));
                defines.put("DISC_BOX_NODES_MAX", Integer.toString(BakedDisc.BOX_NODES_MAX));
                defines.put("DISC_BOX_NODE_TEXELS", Float.toString((float) BakedDisc.BOX_NODE_TEXELS));
                defines.put("DISC_PIECE_UV", Float.toString((float) Math.sin(Math.toRadians(
                        BakedDisc.PIECE_WIDTH_DEG))));
                if (!mapPixel && DiscTable.applies(settings, textures.baked().grid())) {
                    // a wide disc on a surface: the table spread by the disc (disc_table.glsl)
                    double[] cos = DiscTable.memberCos();
                    StringBuilder members = new StringBuilder("float[" + cos.length + "](");
                    for (int k = 0; k < cos.length; k++) {
                        members.append(k > 0 ? ", " : "").append(Float.toString((float) cos[k]));
                    }
                    defines.put("DISC_TABLE", "1");
                    defines.put("DISC_TABLE_MEMBERS", Integer.toString(cos.length));
                    defines.put("DISC_TABLE_COS", members.append(')').toString());
                    defines.put("DISC_TABLE_BLEND", Float.toString((float) DiscTable.BLEND_FRACTION));
                }
            }
        }
        GpuMethods.of(settings.variant()).addDefines(defines, settings, mapPixel);
        return defines;
    }

    /**
     * The bake pass of a table of the method of {@code settings} ({@link GpuMethod#bakeFragmentPath}): its spectral
     * XYZ per (u, v) pixel of one w slice, on the full-screen quad.
     */
    public static ShaderProgram bakeProgram(BrdfSettings settings, DiffractionTextures textures) {
        return bakeProgram(settings, textures.highestOrder(), textures.windowRadii());
    }

    /**
     * A bake pass from what decides its code alone: the settings of the tabulated method (on float32 terms), the
     * terms' order and the window radii. The disk cache keys a table by this program's text too, so a changed shader
     * never reuses a table baked by the old one.
     */
    public static ShaderProgram bakeProgram(BrdfSettings settings, int highestOrder, WindowRadii radii) {
        GpuMethod method = GpuMethods.of(settings.variant());
        if (method.bakeFragmentPath() == null) {
            throw new IllegalArgumentException("no table holds " + settings.variant().spec());
        }
        Map<String, String> defines = defines(settings, highestOrder, radii, null, Target.BRDF_MAP, false, false);
        // as its BRDF map's program of the settings it bakes with, and the bake pass's own switches
        method.addDefines(defines, method.bakeSettings(settings), true);
        method.addBakeDefines(defines, settings);
        return ShaderProgram.fromClasspath(vertexPath(Target.BRDF_MAP), method.bakeFragmentPath(), defines);
    }

    /**
     * The mesh program for these textures, its pixels display values or linear light ({@link FrameOutput}).
     */
    public static ShaderProgram surfaceProgram(BrdfSettings settings, DiffractionTextures textures,
                                               boolean pigmentation, FrameOutput output) {
        Map<String, String> defines = definesFor(settings, textures, Target.SURFACE, false, pigmentation);
        output.addDefines(defines);
        return ShaderProgram.fromClasspath(vertexPath(Target.SURFACE), fragmentPath(settings.variant()), defines);
    }

    /**
     * The BRDF-map program for a window: display sRGB of {@code exposure} x XYZ (define {@code DISPLAY_SRGB})
     * instead of the linear XYZ a float target stores, so an 8-bit framebuffer shows what {@code brdfmap} writes;
     * with {@link FrameOutput#LINEAR} linear sRGB of {@code exposure} x XYZ, unclipped.
     */
    public static ShaderProgram displayBrdfMapProgram(BrdfSettings settings, DiffractionTextures textures,
                                                      FrameOutput output) {
        Map<String, String> defines = definesFor(settings, textures, Target.BRDF_MAP, false, false);
        defines.put("DISPLAY_SRGB", "1");
        output.addDefines(defines);
        return ShaderProgram.fromClasspath(vertexPath(Target.BRDF_MAP), fragmentPath(settings.variant()), defines);
    }

    /**
     * A GLSL {@code mat3(...)} constructor of a row-major matrix. GLSL fills constructors column by column, so
     * the entries are written column-major; 9 significant digits keep the float32 value exact.
     */
    static String glslMat3(double[][] rowMajor) {
        StringBuilder b = new StringBuilder("mat3(");
        for (int col = 0; col < 3; col++) {
            for (int row = 0; row < 3; row++) {
                if (col + row > 0) {
                    b.append(", ");
                }
                b.append(String.format(Locale.ROOT, "%.9e", rowMajor[row][col]));
            }
        }
        return b.append(')').toString();
    }
}
