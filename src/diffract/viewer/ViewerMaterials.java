package diffract.viewer;

import diffract.jrtr.FloatTextureArray;
import diffract.jrtr.GLRenderContext;
import diffract.jrtr.Material;
import diffract.jrtr.Texture2D;
import diffract.optics.BrdfSettings;
import diffract.optics.TaylorTerms;
import diffract.render.DiffractionMaterials;
import diffract.render.DiffractionTextures;

import java.awt.image.BufferedImage;
import java.util.EnumMap;
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
    private TexturesKey texturesKey;
    private DiffractionTextures textures;
    private final Map<DisplayMode, Built> materials = new EnumMap<>(DisplayMode.class);
    private int rebuildCount;

    ViewerMaterials(BufferedImage pigmentation, double diffuseWeight) {
        this.pigmentationTexture = pigmentation == null ? null : new Texture2D(pigmentation);
        this.diffuseWeight = (float) diffuseWeight;
    }

    /** The material for this state's display mode and drawable settings, built if anything it depends on changed. */
    Material materialFor(ViewerState state, GLRenderContext context) {
        BrdfSettings settings = state.drawableSettings();
        TexturesKey wantedTextures = TexturesKey.of(state.terms(), settings);
        if (!wantedTextures.equals(texturesKey)) {
            releaseAll(context);
            textures = DiffractionTextures.of(state.terms(), settings, FloatTextureArray.Precision.FLOAT32);
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

    /** How many materials were built so far (tests: no rebuild per frame). */
    int rebuildCount() {
        return rebuildCount;
    }

    private Material build(DisplayMode mode, BrdfSettings settings, boolean pigmentation, double exposure) {
        if (mode == DisplayMode.BRDF_MAP) {
            return DiffractionMaterials.brdfMapForDisplay(textures, settings, (float) exposure);
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
    }
}
