package diffract.viewer;

import diffract.jrtr.GLRenderContext;
import diffract.jrtr.Material;
import diffract.jrtr.Texture2D;
import diffract.optics.BrdfSettings;
import diffract.optics.TaylorTerms;
import diffract.optics.Variant;
import diffract.pipeline.DiffractionPipeline;
import diffract.render.DiffractionMaterials;
import diffract.render.DiffractionTextures;
import diffract.render.StageResources;
import diffract.scene.DisplayMode;
import diffract.util.Reporter;

import java.awt.image.BufferedImage;
import java.util.EnumMap;
import java.util.Map;
import java.util.Objects;

/**
 * The viewer's diffraction materials, rebuilt only when what they are compiled or uploaded from changes: the
 * term textures when the terms, N, the expansion, the term format or the wavelength grid change; a material when
 * its textures, its program's defines (variant, N, window radius, pigmentation) or its uniforms from the settings
 * change. Per-frame values (light, exposure, map placement) are plain uniform updates. Replaced programs and
 * textures are freed at once. Used on the render thread only.
 */
final class ViewerMaterials {
    /** What the term and wavelength textures are made of; terms compared by identity (they are immutable). */
    private record TexturesKey(TaylorTerms terms, BrdfSettings textureSettings) {
        /**
         * The settings the textures depend on: all of them for a baked table (window, coherence, grid), else
         * only the Taylor group, the wavelengths and the term format.
         */
        static TexturesKey of(TaylorTerms terms, BrdfSettings s) {
            return new TexturesKey(terms, s.variant() == Variant.BAKED ? s
                    : BrdfSettings.builder(Variant.FLSS).taylor(s.taylor()).spectral(s.spectral()).gpu(s.gpu()).build());
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof TexturesKey k && k.terms == terms && k.textureSettings.equals(textureSettings);
        }

        @Override
        public int hashCode() {
            return System.identityHashCode(terms) * 31 + Objects.hashCode(textureSettings);
        }
    }

    private record MaterialKey(BrdfSettings settings, boolean pigmentation) {
    }

    private record Built(MaterialKey key, Material material) {
    }

    private final Texture2D pigmentationTexture;
    private final float diffuseWeight;
    private final DiffractionPipeline pipeline;
    /** The stage's GPU side when the setup stages the surface (scales, environment, ground), else null. */
    private StageResources stage;
    private TexturesKey texturesKey;
    private DiffractionTextures textures;
    private final Map<DisplayMode, Built> materials = new EnumMap<>(DisplayMode.class);
    private int rebuildCount;

    /** @param pipeline the patch's pipeline: it chooses the expansion and keeps the phase-centred terms */
    ViewerMaterials(BufferedImage pigmentation, double diffuseWeight, DiffractionPipeline pipeline) {
        this.pigmentationTexture = pigmentation == null ? null : new Texture2D(pigmentation);
        this.diffuseWeight = (float) diffuseWeight;
        this.pipeline = pipeline;
    }

    /** Draws surfaces on this stage from now on (materials built later use it). */
    void useStage(StageResources stageResources) {
        this.stage = stageResources;
    }

    /** The material for this state's display mode and drawable settings, built if anything it depends on changed. */
    Material materialFor(ViewerState state, GLRenderContext context) {
        BrdfSettings settings = state.drawableSettings();
        TexturesKey wantedTextures = TexturesKey.of(state.terms(), settings);
        if (!wantedTextures.equals(texturesKey)) {
            releaseAll(context);
            // the expansion is decided per N (its estimate depends on N); the pipeline keeps the centred terms
            textures = pipeline.textures(settings, state.terms(), Reporter.STDERR);
            texturesKey = wantedTextures;
        }
        boolean pigmentation = state.view().pigmentationOn() && pigmentationTexture != null;
        MaterialKey key = new MaterialKey(settings, state.view().mode() == DisplayMode.SURFACE && pigmentation);
        Built built = materials.get(state.view().mode());
        if (built == null || !built.key().equals(key)) {
            if (built != null) {
                context.release(built.material().program());
            }
            built = new Built(key, build(state.view().mode(), settings, key.pigmentation(), state.view().exposure()));
            materials.put(state.view().mode(), built);
            rebuildCount++;
        }
        return built.material();
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
