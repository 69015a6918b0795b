package diffract.viewer;

import diffract.jrtr.FloatTextureArray;
import diffract.jrtr.GLRenderContext;
import diffract.jrtr.Material;
import diffract.jrtr.Texture2D;
import diffract.optics.BrdfSettings;
import diffract.optics.Float32Cancellation;
import diffract.optics.HeightField;
import diffract.optics.PhaseCentredTerms;
import diffract.optics.TaylorEvaluation;
import diffract.optics.TaylorTerms;
import diffract.precompute.TaylorTermComputer;
import diffract.render.DiffractionMaterials;
import diffract.render.DiffractionTextures;
import diffract.util.Reporter;

import java.awt.image.BufferedImage;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.Map;

/**
 * The viewer's diffraction materials, rebuilt only when what they are compiled or uploaded from changes: the
 * term textures when the terms, N or the wavelength grid change; a material when its textures, its program's
 * defines (variant, N, window radius, pigmentation) or its uniforms from the settings change. Per-frame values
 * (light, exposure, map placement) are plain uniform updates. Replaced programs and textures are freed at once.
 * Used on the render thread only.
 */
final class ViewerMaterials {
    /** What the term and wavelength textures are made of; terms compared by identity (they are immutable). */
    private record TexturesKey(TaylorTerms terms, int highestOrder, double lambdaMinNm, double lambdaMaxNm,
                               double lambdaStepNm, double taylorTolerance, BrdfSettings baked) {
        /** A baked table depends on all the settings (window, coherence, grid): then they are part of the key. */
        static TexturesKey of(TaylorTerms terms, BrdfSettings s) {
            return new TexturesKey(terms, s.highestOrder(), s.lambdaMinNm(), s.lambdaMaxNm(), s.lambdaStepNm(),
                    s.taylorTolerance(), s.variant() == diffract.optics.Variant.BAKED ? s : null);
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof TexturesKey k && k.terms == terms && k.highestOrder == highestOrder
                    && k.lambdaMinNm == lambdaMinNm && k.lambdaMaxNm == lambdaMaxNm && k.lambdaStepNm == lambdaStepNm
                    && k.taylorTolerance == taylorTolerance && java.util.Objects.equals(k.baked, baked);
        }

        @Override
        public int hashCode() {
            return System.identityHashCode(terms) * 31 + highestOrder;
        }
    }

    private record MaterialKey(BrdfSettings settings, boolean pigmentation) {
    }

    private record Built(MaterialKey key, Material material) {
    }

    private final Texture2D pigmentationTexture;
    private final float diffuseWeight;
    /** The stage's GPU side when the setup stages the surface (scales, environment, ground), else null. */
    private diffract.render.StageResources stage;
    private final HeightField patch;
    /** The phase-centred terms of the patch (issue #6) by the shortest wavelength they were planned for. */
    /** The phase-centred terms per shortest wavelength (they do not depend on N; the decision does). */
    private final Map<Double, PhaseCentredTerms> centredByLambdaMin = new HashMap<>();
    private TexturesKey texturesKey;
    private DiffractionTextures textures;
    private final Map<DisplayMode, Built> materials = new EnumMap<>(DisplayMode.class);
    private int rebuildCount;

    /** @param patch the mean-subtracted height field the terms belong to (for the phase-centred expansion) */
    ViewerMaterials(BufferedImage pigmentation, double diffuseWeight, HeightField patch) {
        this.pigmentationTexture = pigmentation == null ? null : new Texture2D(pigmentation);
        this.diffuseWeight = (float) diffuseWeight;
        this.patch = patch;
    }

    /** Draws surfaces on this stage from now on (materials built later use it). */
    void useStage(diffract.render.StageResources stageResources) {
        this.stage = stageResources;
    }

    /** The material for this state's display mode and drawable settings, built if anything it depends on changed. */
    Material materialFor(ViewerState state, GLRenderContext context) {
        BrdfSettings settings = state.drawableSettings();
        TexturesKey wantedTextures = TexturesKey.of(state.terms(), settings);
        if (!wantedTextures.equals(texturesKey)) {
            releaseAll(context);
            textures = termTextures(state.terms(), settings);
            texturesKey = wantedTextures;
        }
        boolean pigmentation = state.pigmentationOn() && pigmentationTexture != null;
        MaterialKey key = new MaterialKey(settings, state.mode() == DisplayMode.SURFACE && pigmentation);
        Built built = materials.get(state.mode());
        if (built == null || !built.key().equals(key)) {
            if (built != null) {
                context.release(built.material().program());
            }
            built = new Built(key, build(state.mode(), settings, key.pigmentation(), state.exposure()));
            materials.put(state.mode(), built);
            rebuildCount++;
        }
        return built.material();
    }

    /**
     * The thesis' terms where their float32 series is accurate for this patch, else the phase-centred expansion, as
     * the settings' expansion mode says (AUTO; PLAIN for auto's choice, which was calibrated on that path)
     * (issue #6, {@link TaylorEvaluation}): decided per N, since the estimate depends on it; the centred terms are
     * computed once per shortest wavelength, on this thread (a fraction of a second for the patches the viewer
     * shows). The decision and its reason are printed whenever the textures change.
     */
    private DiffractionTextures termTextures(TaylorTerms terms, BrdfSettings settings) {
        if (settings.expansion() == TaylorEvaluation.Mode.PLAIN || settings.expansion() == TaylorEvaluation.Mode.AUTO
                && Float32Cancellation.plainSeriesSuffices(terms, settings.highestOrder(), settings.lambdaMinNm())) {
            return DiffractionTextures.of(terms, settings, FloatTextureArray.Precision.FLOAT32);
        }
        // decided for this N (the estimate depends on it); the centred terms are computed once per lambda_min
        TaylorEvaluation evaluation = TaylorEvaluation.choose(settings.expansion(), patch, terms,
                settings.highestOrder(), settings.lambdaMinNm(), (p, centres) -> centredByLambdaMin.computeIfAbsent(
                        settings.lambdaMinNm(), lambdaMin -> TaylorTermComputer.computeCentred(p, centres, Reporter.SILENT)),
                Reporter.STDERR);
        return evaluation.isPhaseCentred()
                ? DiffractionTextures.ofPhaseCentred(evaluation.centredTerms(), settings, FloatTextureArray.Precision.FLOAT32)
                : DiffractionTextures.of(terms, settings, FloatTextureArray.Precision.FLOAT32);
    }

    /** How many materials were built so far (tests: no rebuild per frame). */
    int rebuildCount() {
        return rebuildCount;
    }

    private Material build(DisplayMode mode, BrdfSettings settings, boolean pigmentation, double exposure) {
        if (mode == DisplayMode.BRDF_MAP) {
            return DiffractionMaterials.brdfMapForDisplay(textures, settings, (float) exposure);
        }
        if (stage != null) {
            return stage.surface(textures, settings, (float) exposure, pigmentation ? pigmentationTexture : null,
                    diffuseWeight);
        }
        return DiffractionMaterials.surface(textures, settings, (float) exposure,
                pigmentation ? pigmentationTexture : null, diffuseWeight);
    }

    /** Frees the textures and all programs made from them (not the pigmentation image, which never changes). */
    private void releaseAll(GLRenderContext context) {
        for (Built built : materials.values()) {
            context.release(built.material().program());
        }
        materials.clear();
        if (textures != null) {
            context.release(textures.terms());
            context.release(textures.uniformNodeTable());
            context.release(textures.spectralTable());
            if (textures.bakedTexture() != null) {
                context.release(textures.bakedTexture());
            }
            textures = null;
            texturesKey = null;
        }
    }

    /** Frees everything, the pigmentation texture included (the context is about to go). */
    void releaseAll(GLRenderContext context, boolean includingPigmentation) {
        releaseAll(context);
        if (includingPigmentation && pigmentationTexture != null) {
            context.release(pigmentationTexture);
        }
        if (includingPigmentation && stage != null) {
            stage.release(context);
        }
    }
}
