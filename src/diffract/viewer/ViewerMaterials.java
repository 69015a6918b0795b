package diffract.viewer;

import diffract.jrtr.GLRenderContext;
import diffract.jrtr.scenegraph.Material;
import diffract.jrtr.textures.Texture2D;
import diffract.optics.BrdfSettings;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.Methods;
import diffract.pipeline.DiffractionPipeline;
import diffract.render.DiffractionMaterials;
import diffract.render.DiffractionTextures;
import diffract.render.FrameOutput;
import diffract.render.StageResources;
import diffract.scene.DisplayMode;
import diffract.util.Reporter;

import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;

/**
 * The viewer's diffraction materials, built only when what they are compiled or uploaded from changes: the term
 * textures when the terms, N, the expansion, the term format or the wavelength grid change; a material when its
 * textures, its program's defines (variant, N, window radius, pigmentation) or its uniforms from the settings
 * change. Per-frame values (light, exposure, map placement) are plain uniform updates. A few of each are kept, the
 * least recently used freed beyond that: the window alternates between a preview's settings and the configured
 * ones ({@link PreviewPolicy}), and between the two sides of an A/B split, and none is rebuilt when it comes back. Used on the render thread only.
 */
final class ViewerMaterials {
    /** Sets of term textures kept: the preview's and the configured settings', of each side of an A/B split. */
    static final int KEPT_TEXTURES = 4;
    /** Materials kept: the preview's and the configured settings', each for a surface and a BRDF map, per side. */
    static final int KEPT_MATERIALS = 8;

    /** What the term and wavelength textures are made of; terms compared by identity (they are immutable). */
    private record TexturesKey(TaylorTerms terms, BrdfSettings textureSettings) {
        /**
         * The settings the textures depend on: all of them for a baked table (window, coherence, grid), else
         * only the Taylor group, the wavelengths and the term format.
         */
        static TexturesKey of(TaylorTerms terms, BrdfSettings s) {
            return new TexturesKey(terms, s.variant().drawsTable() ? s : BrdfSettings.builder(Methods.Role.FALLBACK.method())
                    .taylor(s.taylor()).spectral(s.spectral()).gpu(s.gpu()).build());
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

    private record MaterialKey(TexturesKey textures, DisplayMode mode, BrdfSettings settings, boolean pigmentation) {
    }

    private final Texture2D pigmentationTexture;
    private final float diffuseWeight;
    private final DiffractionPipeline pipeline;
    private final FrameOutput output;
    /** The stage's GPU side when the setup stages the surface (scales, environment, ground), else null. */
    private StageResources stage;
    private final LinkedHashMap<TexturesKey, DiffractionTextures> textures = new LinkedHashMap<>(4, 0.75f, true);
    private final LinkedHashMap<MaterialKey, Material> materials = new LinkedHashMap<>(8, 0.75f, true);
    private int rebuildCount;

    /**
     * @param pipeline the patch's pipeline: it chooses the expansion and keeps the phase-centred terms
     * @param output   what the frames' pixels hold: display values, or linear light for a still kept as floats
     */
    ViewerMaterials(Texture2D pigmentation, double diffuseWeight, DiffractionPipeline pipeline, FrameOutput output) {
        this.pigmentationTexture = pigmentation;
        this.diffuseWeight = (float) diffuseWeight;
        this.pipeline = pipeline;
        this.output = output;
    }

    /** Draws surfaces on this stage from now on (materials built later use it). */
    void useStage(StageResources stageResources) {
        this.stage = stageResources;
    }

    /** The material for this state's display mode drawn with {@code settings}, built if not at hand. */
    Material materialFor(ViewerState state, BrdfSettings settings, GLRenderContext context) {
        TexturesKey texturesKey = TexturesKey.of(state.terms(), settings);
        DiffractionTextures t = textures.get(texturesKey);
        if (t == null) {
            // the expansion is decided per N (its estimate depends on N); the pipeline keeps the centred terms
            t = pipeline.textures(settings, state.terms(), Reporter.STDERR);
            textures.put(texturesKey, t);
            dropOldTextures(context);
        }
        DisplayMode mode = state.view().mode();
        boolean pigmentation = mode == DisplayMode.SURFACE && state.view().pigmentationOn()
                && pigmentationTexture != null;
        MaterialKey key = new MaterialKey(texturesKey, mode, settings, pigmentation);
        Material material = materials.get(key);
        if (material == null) {
            material = build(t, mode, settings, pigmentation, state.view().exposure());
            materials.put(key, material);
            rebuildCount++;
            dropOldMaterials(context);
        }
        return material;
    }

    /** How many materials were built so far (tests: no rebuild per frame). */
    int rebuildCount() {
        return rebuildCount;
    }

    private Material build(DiffractionTextures t, DisplayMode mode, BrdfSettings settings, boolean pigmentation,
                           double exposure) {
        if (mode == DisplayMode.BRDF_MAP) {
            return DiffractionMaterials.brdfMapForDisplay(t, settings, (float) exposure, output);
        }
        if (stage != null) {
            return stage.surface(t, settings, (float) exposure, pigmentation ? pigmentationTexture : null,
                    diffuseWeight, Reporter.STDERR);
        }
        return DiffractionMaterials.surface(t, settings, (float) exposure, pigmentation ? pigmentationTexture : null,
                diffuseWeight, output);
    }

    private void dropOldMaterials(GLRenderContext context) {
        Iterator<Map.Entry<MaterialKey, Material>> eldest = materials.entrySet().iterator();
        while (materials.size() > KEPT_MATERIALS) {
            context.release(eldest.next().getValue().program());
            eldest.remove();
        }
    }

    /** Frees the least recently used textures beyond {@link #KEPT_TEXTURES}, and the materials made from them. */
    private void dropOldTextures(GLRenderContext context) {
        Iterator<Map.Entry<TexturesKey, DiffractionTextures>> eldest = textures.entrySet().iterator();
        while (textures.size() > KEPT_TEXTURES) {
            Map.Entry<TexturesKey, DiffractionTextures> dropped = eldest.next();
            eldest.remove();
            materials.entrySet().removeIf(m -> {
                boolean usesThem = m.getKey().textures().equals(dropped.getKey());
                if (usesThem) {
                    context.release(m.getValue().program());
                }
                return usesThem;
            });
            release(context, dropped.getValue());
        }
    }

    private static void release(GLRenderContext context, DiffractionTextures t) {
        context.release(t.terms());
        context.release(t.uniformNodeTable());
        context.release(t.spectralTable());
        t.tables().made().forEach(context::release);
    }

    /** Frees all programs and textures (not the pigmentation image or the stage, which the renderer owns). */
    void releaseAll(GLRenderContext context) {
        for (Material m : materials.values()) {
            context.release(m.program());
        }
        materials.clear();
        for (DiffractionTextures t : textures.values()) {
            release(context, t);
        }
        textures.clear();
    }
}
