package diffract.optics;

import diffract.util.UserInputException;

/**
 * Everything that decides how a variant evaluates the BRDF. Defaults are the thesis' configuration
 * (001 implementation notes; 003 section 1.3.2): 30 Taylor terms, a 3 x 3 window, 5 nm steps over 380-780 nm,
 * 4 sigma_s = 65 um, refractive index 1.5. The reference ignores terms, window radius and lambda step.
 *
 * @param highestOrder  N, the last Taylor order (N + 1 terms)
 * @param windowRadius  R texels: a (2R + 1)^2 window
 * @param lambdaStepNm  FLSS/PQ step, and NMM's fallback step near the specular direction
 * @param pqReplicas    PQ replicas per axis; 0 = enough to span the coherence length 4 sigma_s
 */
public record BrdfSettings(Variant variant, int highestOrder, int windowRadius, double lambdaMinNm,
                           double lambdaMaxNm, double lambdaStepNm, double sigmaSpatialUm,
                           double refractiveIndex, int pqReplicas) {

    public static final double LAMBDA_MIN_NM = 380;
    public static final double LAMBDA_MAX_NM = 780;
    /** The reference integrates at 1 nm (issue #2). */
    public static final double REFERENCE_STEP_NM = 1.0;

    public BrdfSettings {
        if (highestOrder < 0) {
            throw new UserInputException("the number of Taylor terms must be at least 1 (highest order >= 0)");
        }
        if (windowRadius < 0) {
            throw new UserInputException("the window radius must be >= 0 texels, got " + windowRadius);
        }
        if (!(lambdaMinNm > 0) || !(lambdaMaxNm > lambdaMinNm)) {
            throw new UserInputException("need 0 < lambda-min < lambda-max, got " + lambdaMinNm + " and " + lambdaMaxNm);
        }
        if (!(lambdaStepNm > 0)) {
            throw new UserInputException("the lambda step must be > 0 nm, got " + lambdaStepNm);
        }
        if (!(sigmaSpatialUm > 0)) {
            throw new UserInputException("sigma_s must be > 0 um, got " + sigmaSpatialUm);
        }
        if (!(refractiveIndex >= 1.0)) {
            throw new UserInputException("the refractive index must be >= 1, got " + refractiveIndex);
        }
        if (pqReplicas < 0) {
            throw new UserInputException("PQ replicas must be >= 0 (0 = automatic), got " + pqReplicas);
        }
    }

    /** The thesis' configuration for a variant. */
    public static BrdfSettings thesis(Variant variant) {
        return new BrdfSettings(variant, 30, 1, LAMBDA_MIN_NM, LAMBDA_MAX_NM, 5.0,
                CoherenceWindow.COHERENCE_LENGTH_UM / 4.0, GainFactor.SNAKE_SKIN_REFRACTIVE_INDEX, 0);
    }

    public BrdfSettings withVariant(Variant v) {
        return new BrdfSettings(v, highestOrder, windowRadius, lambdaMinNm, lambdaMaxNm, lambdaStepNm,
                sigmaSpatialUm, refractiveIndex, pqReplicas);
    }

    public BrdfSettings withHighestOrder(int n) {
        return new BrdfSettings(variant, n, windowRadius, lambdaMinNm, lambdaMaxNm, lambdaStepNm,
                sigmaSpatialUm, refractiveIndex, pqReplicas);
    }

    public BrdfSettings withWindowRadius(int r) {
        return new BrdfSettings(variant, highestOrder, r, lambdaMinNm, lambdaMaxNm, lambdaStepNm,
                sigmaSpatialUm, refractiveIndex, pqReplicas);
    }

    public BrdfSettings withLambdaStepNm(double step) {
        return new BrdfSettings(variant, highestOrder, windowRadius, lambdaMinNm, lambdaMaxNm, step,
                sigmaSpatialUm, refractiveIndex, pqReplicas);
    }

    public BrdfSettings withLambdaRangeNm(double min, double max) {
        return new BrdfSettings(variant, highestOrder, windowRadius, min, max, lambdaStepNm,
                sigmaSpatialUm, refractiveIndex, pqReplicas);
    }

    public CoherenceWindow coherenceWindow() {
        return new CoherenceWindow(sigmaSpatialUm);
    }

    /** The lambda step this variant actually integrates with (1 nm for the reference). */
    public double effectiveLambdaStepNm() {
        return variant == Variant.REFERENCE ? REFERENCE_STEP_NM : lambdaStepNm;
    }
}
