package diffract.render;

import diffract.jrtr.Material;
import diffract.jrtr.Texture2D;
import diffract.optics.BakedGrid;
import diffract.optics.BrdfSettings;
import diffract.optics.CoherenceWindow;
import diffract.optics.Covariance2;
import diffract.optics.Direction;
import diffract.optics.GaussHermite;
import diffract.optics.LightSource;
import diffract.optics.LobeQuadrature;
import diffract.optics.LobeWeightTable;
import diffract.optics.OpticsOptions;
import diffract.optics.PhaseCentres;
import diffract.optics.PixelFilter;
import diffract.optics.TaylorSincSpectrum;
import diffract.optics.Variant;
import diffract.util.UserInputException;

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
        return brdfMap(textures, settings, OpticsOptions.POINT_SAMPLED, monochromatic);
    }

    /**
     * As above with the optics options (Fresnel model; for the lobes method the pixel filter and the light, whose
     * uniforms {@link #setLight(Material, Direction, OpticsOptions)} sets with omega_i).
     */
    public static Material brdfMap(DiffractionTextures textures, BrdfSettings settings, OpticsOptions options,
                                   boolean monochromatic) {
        Material m = new Material(DiffractionShaders.program(settings, textures, options,
                DiffractionShaders.Target.BRDF_MAP, monochromatic, false));
        return common(m, textures, settings, options);
    }

    /**
     * A BRDF-map material that outputs display sRGB of {@code exposure} x XYZ, for windows (8-bit framebuffers).
     * Set {@code omegaI} with {@link #setLight}, {@code mapSizePx}, and {@code mapOriginPx} (the map's lower-left
     * corner in the viewport, to centre it) before drawing.
     */
    public static Material brdfMapForDisplay(DiffractionTextures textures, BrdfSettings settings, float exposure) {
        Material m = new Material(DiffractionShaders.displayBrdfMapProgram(settings, textures));
        return common(m, textures, settings, OpticsOptions.POINT_SAMPLED).setFloat("exposure", exposure);
    }

    /**
     * A mesh material (003 Algorithms 2-4): display sRGB of exposure x XYZ, blended with {@code pigmentation}
     * (display-encoded sRGB, or null for pure structural colour) with diffuse weight w_d.
     */
    public static Material surface(DiffractionTextures textures, BrdfSettings settings, float exposure,
                                   Texture2D pigmentation, float diffuseWeight) {
        return surface(textures, settings, OpticsOptions.POINT_SAMPLED, exposure, pigmentation, diffuseWeight);
    }

    /** As above with the optics options (the lobes method's pixels average over their footprint and the light). */
    public static Material surface(DiffractionTextures textures, BrdfSettings settings, OpticsOptions options,
                                   float exposure, Texture2D pigmentation, float diffuseWeight) {
        Material m = new Material(DiffractionShaders.program(settings, textures, options,
                DiffractionShaders.Target.SURFACE, false, pigmentation != null));
        common(m, textures, settings, options).setFloat("exposure", exposure);
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
        return common(m, textures, flssSettings, OpticsOptions.POINT_SAMPLED).setVec2("bakedSamples", grid.uvSamples(),
                grid.wSamples());
    }

    /**
     * The bake pass of a BAKED table of the lobes method: every sample averaged over its cell of the grid and the
     * light ({@code setTableCell} in {@code lobes_footprint.glsl}).
     */
    static Material bakeLobes(DiffractionTextures textures, BrdfSettings lobesSettings, BakedGrid grid,
                              OpticsOptions options) {
        Material m = new Material(DiffractionShaders.bakeLobesProgram(lobesSettings, textures));
        return common(m, textures, lobesSettings, options.withPixelFilter(PixelFilter.BOX))
                .setVec2("bakedSamples", grid.uvSamples(), grid.wSamples());
    }

    /** omega_i of a BRDF map (towards the light, tangent frame), a point light. */
    public static Material setLight(Material brdfMap, Direction wi) {
        return setLight(brdfMap, wi, OpticsOptions.POINT_SAMPLED);
    }

    /**
     * omega_i of a BRDF map and, for the lobes method, the light's (u, v) covariance at omega_i, split into its
     * diagonal part and Gauss-Hermite shifts along the rest ({@link Covariance2#diagonalPlusRankOne}), which every
     * pixel of the map shares.
     */
    public static Material setLight(Material brdfMap, Direction wi, OpticsOptions options) {
        brdfMap.setVec3("omegaI", (float) wi.x(), (float) wi.y(), (float) wi.z());
        LightSource light = options.light();
        Covariance2 c = light.uvCovariance(wi);
        double[] split = c.isDiagonal() ? new double[] {c.xx(), c.yy(), 1, 0, 0} : c.diagonalPlusRankOne();
        brdfMap.setVec2("lightDiagonal", (float) split[0], (float) split[1]);
        brdfMap.setVec3("lightRankOne", (float) (split[4] * split[2] * split[2]),
                (float) (split[4] * split[2] * split[3]), (float) (split[4] * split[3] * split[3]));
        float[] shifts = new float[3 * LIGHT_NODES_MAX];
        int count = 0;
        if (split[4] > 0) {
            double sigma = Math.sqrt(split[4]);
            double[] nodes = GaussHermite.nodes(options.lobes().lightNodes());
            double[] weights = GaussHermite.weights(options.lobes().lightNodes());
            for (int k = 0; k < nodes.length; k++) {
                shifts[3 * k] = (float) (sigma * nodes[k] * split[2]);
                shifts[3 * k + 1] = (float) (sigma * nodes[k] * split[3]);
                shifts[3 * k + 2] = (float) weights[k];
            }
            count = nodes.length;
        }
        return brdfMap.setFloatArray("lightShifts", shifts).setInt("lightShiftCount", count)
                .setFloat("lightSigmaRad", (float) light.sigmaRad());
    }

    /** The shader's light arrays hold this many Gauss-Hermite shifts (lobes_footprint.glsl). */
    static final int LIGHT_NODES_MAX = 8;

    /**
     * The lobes method's uniforms: spectral weights, quadrature, pixel filter and light size. The shader sums whole
     * texels only: a patch whose window keeps pairs of texels at the quadrature's threshold is refused.
     */
    private static void lobes(Material m, DiffractionTextures textures, BrdfSettings settings, OpticsOptions options) {
        CoherenceWindow window = settings.coherenceWindow();
        LobeQuadrature q = options.lobes();
        int kx = LobeQuadrature.pairRadius(window.sigmaTexels(textures.extentXUm()), q.pairThreshold());
        int ky = LobeQuadrature.pairRadius(window.sigmaTexels(textures.extentYUm()), q.pairThreshold());
        if (kx > 0 || ky > 0) {
            throw new UserInputException(String.format(java.util.Locale.ROOT, "the lobes shader sums whole texels, but "
                    + "this %.1f x %.1f um patch at a %.0f um coherence length has sigma_f = %.2f texels: texel pairs "
                    + "weigh more than the pair threshold %.0e; render it on the CPU (--engine cpu), or with a shorter "
                    + "--coherence-length or a smaller patch", textures.extentXUm(), textures.extentYUm(),
                    4 * settings.sigmaSpatialUm(), window.sigmaTexels(Math.max(textures.extentXUm(),
                    textures.extentYUm())), q.pairThreshold()));
        }
        LobeWeightTable table = textures.lobeWeightTable(settings, q);
        m.setTexture("lobeWeights", textures.lobeWeights(settings, q))
                .setInt("lobeWeightSamples", table.samples())
                .setFloat("lobePhaseStepPerUm", (float) table.stepPerUm())
                .setFloat("lobeMaxPhasePerUm", (float) table.maxPhasePerUm())
                .setFloat("lobeCutoff", (float) q.cutoff());
        m.setTexture("lobeSpectralTable", textures.lobeSpectralTable(settings))
                .setInt("lobeTablePositions", textures.lobeSpectralTablePositions(settings))
                .setFloat("lobeNodesPerSigma", (float) q.nodesPerSigma())
                .setFloat("lobeMaxStepNm", (float) q.maxStepNm())
                .setFloat("lobeReachSigmas", (float) q.reachSigmas())
                .setFloat("pixelFootprintScale", options.pixelFilter() == PixelFilter.BOX ? 1f : 0f)
                .setFloat("lightSigmaRad", (float) options.light().sigmaRad());
    }

    private static Material common(Material m, DiffractionTextures textures, BrdfSettings settings,
                                   OpticsOptions options) {
        if (settings.variant() == Variant.LOBES) {
            lobes(m, textures, settings, options);
        }
        double extentX = textures.extentXUm();
        double extentY = textures.extentYUm();
        CoherenceWindow window = settings.coherenceWindow();
        // the replica counts of DiffractionBrdf.create(PQ)
        int replicasX = settings.pqReplicas() > 0 ? settings.pqReplicas()
                : TaylorSincSpectrum.replicasForCoherence(window, extentX);
        int replicasY = settings.pqReplicas() > 0 ? settings.pqReplicas()
                : TaylorSincSpectrum.replicasForCoherence(window, extentY);
        if (textures.baked() != null) {
            // the baked lookup reads its table only: the terms stay on the CPU (they were used by the bake)
            BakedGrid grid = textures.baked().grid();
            m.setTexture(textures.baked().filtered() ? "bakedLayers" : "bakedXyz", textures.bakedTexture())
                    .setVec2("bakedSamples", grid.uvSamples(), grid.wSamples());
        } else {
            m.setTexture("taylorTerms", textures.terms())
                    .setTexture("uniformNodeTable", textures.uniformNodeTable())
                    .setTexture("spectralTable", textures.spectralTable());
            if (textures.normalisedTerms()) {
                m.setTexture("termExtrema", textures.termExtrema());
            }
        }
        PhaseCentres centres = textures.phaseCentres();
        if (centres != null) { // taylor_centred.glsl
            m.setFloat("centreSpacingPerUm", (float) centres.spacingPerUm()).setInt("centreCount", centres.centreCount());
        }
        m.setFloat("taylorTolerance", (float) settings.taylorTolerance())
                .setFloat("maxAbsHeightUm", (float) textures.maxAbsHeightUm());
        return m.setVec2("patchExtentUm", (float) extentX, (float) extentY)
                .setFloat("refractiveIndex", (float) settings.refractiveIndex())
                .setVec2("sigmaTexels", (float) window.sigmaTexels(extentX), (float) window.sigmaTexels(extentY))
                .setVec2("pqReplicas", replicasX, replicasY)
                .setFloat("lambdaMinNm", (float) settings.lambdaMinNm())
                .setFloat("lambdaMaxNm", (float) settings.lambdaMaxNm())
                .setFloat("spectralTableFirstNm", (float) textures.spectralTableFirstNm());
    }
}
