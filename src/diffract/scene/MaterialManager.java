package diffract.scene;

import diffract.geometry.PigmentationTexture;
import diffract.optics.BrdfSettings;
import diffract.optics.HeightField;
import diffract.optics.TaylorBound;
import diffract.optics.io.HeightFieldReader;
import diffract.optics.io.SamplingCheck;
import diffract.precompute.Precomputation;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import diffract.viewer.PigmentationImage;
import diffract.viewer.TermSource;

import java.awt.image.BufferedImage;
import java.nio.file.Path;

/**
 * The material's constants manager (the thesis' patch and shader constants): the height field (read or made by
 * code, mean-subtracted), the BRDF settings with N fixed (a tolerance is turned into N by the Lagrange bound, 001
 * sec. 3.3.3), the pigmentation image, and where Taylor terms come from: the user cache, computed with progress
 * on first use.
 */
final class MaterialManager {
    /** The procedural corn-snake pigmentation is the same every run (and the same as {@code --shape snake}). */
    static final long PIGMENT_SEED = 2014;

    private final Scene.MaterialSpec spec;
    private final HeightField patch;
    private final String patchName;
    private final BrdfSettings settings;

    MaterialManager(Scene.MaterialSpec spec, Reporter reporter) {
        this.spec = spec;
        if (spec.patch() instanceof Scene.FilePatch file) {
            patch = HeightFieldReader.load(file.file(), file.maxHeightUm(), file.pixelSizeUm(), reporter).meanSubtracted();
            patchName = file.file().getFileName().toString();
        } else {
            Scene.ProceduralPatch procedural = (Scene.ProceduralPatch) spec.patch();
            patch = procedural.spec().build().meanSubtracted();
            patchName = procedural.spec().displayName();
        }
        int highestOrder = spec.taylorTerms() != null ? spec.taylorTerms()
                : TaylorBound.termsForTolerance(TaylorBound.maxPhase(spec.lambdaMinNm(), patch.maxAbsHeightUm()),
                spec.tolerance());
        if (highestOrder > diffract.viewer.ViewerController.MAX_HIGHEST_ORDER) {
            throw new UserInputException("material.tolerance " + spec.tolerance() + " needs N = " + highestOrder
                    + " Taylor terms for this patch; the viewer draws at most "
                    + diffract.viewer.ViewerController.MAX_HIGHEST_ORDER + ": use a larger tolerance");
        }
        settings = new BrdfSettings(spec.variant(), highestOrder, spec.windowRadius(), spec.lambdaMinNm(),
                spec.lambdaMaxNm(), spec.lambdaStepNm(), spec.sigmaSpatialUm(), spec.refractiveIndex(), 0);
        SamplingCheck.warnAboutAliasing(patch, settings.lambdaMinNm(), settings.lambdaMaxNm(), reporter);
    }

    HeightField patch() {
        return patch;
    }

    String patchName() {
        return patchName;
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

    /** Terms 0..n of the patch from the user cache, keyed by patch content and n; computed with progress if new. */
    TermSource termSource() {
        Double maxHeightUm = spec.patch() instanceof Scene.FilePatch file ? file.maxHeightUm() : null;
        return (n, reporter) -> Precomputation.cached(new Precomputation.Request(patch, patchName, maxHeightUm, n, null,
                settings.lambdaMinNm()), reporter);
    }
}
