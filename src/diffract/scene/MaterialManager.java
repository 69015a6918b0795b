package diffract.scene;

import diffract.geometry.PigmentationTexture;
import diffract.optics.BrdfSettings;
import diffract.optics.patches.HeightField;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.LightPolicy;
import diffract.optics.Methods;
import diffract.optics.patches.PatchCatalogue;
import diffract.optics.settings.PixelFilter;
import diffract.optics.settings.Quantity;
import diffract.optics.spectra.TaylorBound;
import diffract.optics.spectra.TaylorSettings;
import diffract.optics.Variant;
import diffract.optics.io.HeightFieldReader;
import diffract.optics.io.SamplingCheck;
import diffract.pipeline.DiffractionPipeline;
import diffract.pipeline.NamedPatch;
import diffract.util.Reporter;

import java.awt.image.BufferedImage;

/**
 * The material's constants manager (the thesis' patch and shader constants): the height field (read or made by
 * code, mean-subtracted) and its {@link DiffractionPipeline} (terms from the user cache, computed with progress on
 * first use), the BRDF settings with N fixed (a tolerance is turned into N by the Lagrange bound, 001 sec. 3.3.3),
 * and the pigmentation image.
 */
final class MaterialManager {
    /** The procedural corn-snake pigmentation is the same every run. */
    static final long PIGMENT_SEED = 2014;

    private final Scene.MaterialSpec spec;
    private final DiffractionPipeline pipeline;
    private final BrdfSettings settings;

    MaterialManager(Scene.MaterialSpec spec, Reporter reporter) {
        this.spec = spec;
        NamedPatch patch;
        if (spec.patch() instanceof Scene.FilePatch file) {
            HeightField field = HeightFieldReader.load(file.file(), file.maxHeightUm(), file.pixelSizeUm(),
                    file.channel(), file.levelling(), reporter);
            patch = new NamedPatch(file.file().getFileName().toString(), field.meanSubtracted(), file.maxHeightUm());
        } else {
            Scene.ProceduralPatch procedural = (Scene.ProceduralPatch) spec.patch();
            boolean asCatalogued = procedural.spec().equals(PatchCatalogue.named(procedural.name()).spec());
            patch = NamedPatch.of(asCatalogued ? procedural.name()
                    : procedural.name() + "(" + procedural.spec().periodUm() + " um)", procedural.spec().build());
        }
        BrdfSettings s = spec.settings();
        if (spec.orderTolerance() != null) {
            int n = TaylorBound.termsForTolerance(TaylorBound.maxPhase(s.spectral().lambdaMinNm(),
                    patch.meanSubtracted().maxAbsHeightUm()), spec.orderTolerance());
            if (n > TaylorSettings.MAX_HIGHEST_ORDER) {
                throw new InvalidSettingException(Quantity.ORDER_TOLERANCE, "the tolerance " + spec.orderTolerance()
                        + " needs N = " + n + " Taylor terms for this patch, above the limit "
                        + TaylorSettings.MAX_HIGHEST_ORDER + ": use a larger tolerance");
            }
            s = s.with(b -> b.highestOrder(n));
        }
        HeightField field = patch.meanSubtracted();
        var refusal = s.variant().patchRefusal(s, field.cols() * field.pixelSizeXUm(),
                field.rows() * field.pixelSizeYUm());
        if (refusal.isPresent()) {
            // a scene that asks for a method that refuses its patch still renders: the fallback method, which
            // point-samples the light, under a point light (said once)
            Variant fallback = Methods.Role.FALLBACK.method();
            reporter.warn(refusal.get() + ": drawing it with " + fallback.spec() + " under a point light instead");
            s = s.with(b -> b.drawnBy(fallback).lightSizeDeg(0).pixelFilter(PixelFilter.POINT));
        }
        // a point-sampling variant asked for on a scene lit by an extended light (the sun by default): it samples
        // the light at its centre, said once
        LightPolicy light = LightPolicy.of(s);
        light.notice().ifPresent(reporter::warn);
        // drawn for the exposure the scene is shown at (the lobes method's cutoff, LobeQuadrature.shownAt)
        s = light.usable().shownAt(spec.exposure());
        settings = s;
        pipeline = DiffractionPipeline.cached(patch, settings.spectral().lambdaMinNm());
        SamplingCheck.warnAboutAliasing(patch.meanSubtracted(), settings.spectral().lambdaMinNm(),
                settings.spectral().lambdaMaxNm(), reporter);
    }

    DiffractionPipeline pipeline() {
        return pipeline;
    }

    /** The patch's height field, mean-subtracted. */
    HeightField field() {
        return pipeline.patch().meanSubtracted();
    }

    BrdfSettings settings() {
        return settings;
    }

    /** Display-encoded sRGB pigment colours, or null for "none". */
    BufferedImage pigmentation() {
        Scene.PigmentationSpec pigmentation = spec.pigmentation();
        if (pigmentation.procedural()) {
            return new PigmentationTexture(PigmentationTexture.Parameters.defaults(PIGMENT_SEED)).image(256, 2048);
        }
        return pigmentation.file() == null ? null : PigmentationImage.read(pigmentation.file());
    }
}
