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
 * @param taylorTolerance each fragment's Taylor loop stops at the first order n whose Lagrange remainder
 *                      x^(n+1) e^x / (n+1)! (x = k |w| max|h| of that fragment; 001 sec. 3.3.3) is at most this;
 *                      0 = always the fixed N (the thesis' behaviour, bit-identical)
 * @param automaticWindowRadius the window radius per axis follows sigma_f in texels ({@link WindowRadii#automatic})
 *                      instead of the fixed {@code windowRadius}
 * @param bakedUvSamples BAKED: samples of the table along u and along v over [-2, 2]; 0 = automatic
 *                      ({@link BakedGrid#automaticUvSamples})
 * @param bakedWSamples BAKED: samples along w over [-2, 0]; 0 = automatic ({@link BakedGrid#automaticWSamples})
 * @param expansion     which Taylor expansion flss/nmm/pq sum (issue #6, {@link TaylorEvaluation}): AUTO (the
 *                      thesis' series where it is accurate for the patch, else phase-centred), PLAIN or CENTRED
 */
public record BrdfSettings(Variant variant, int highestOrder, int windowRadius, double lambdaMinNm,
                           double lambdaMaxNm, double lambdaStepNm, double sigmaSpatialUm,
                           double refractiveIndex, int pqReplicas, double taylorTolerance,
                           boolean automaticWindowRadius, int bakedUvSamples, int bakedWSamples,
                           TaylorEvaluation.Mode expansion) {

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
        if (!(taylorTolerance >= 0) || !Double.isFinite(taylorTolerance)) {
            throw new UserInputException("the Taylor tolerance must be >= 0 (0 = fixed N), got " + taylorTolerance);
        }
        if (bakedUvSamples != 0 && (bakedUvSamples < 2 || bakedUvSamples > BakedGrid.MAX_SAMPLES)) {
            throw new UserInputException("baked (u, v) samples must be 0 (automatic) or 2.." + BakedGrid.MAX_SAMPLES
                    + ", got " + bakedUvSamples);
        }
        if (bakedWSamples != 0 && (bakedWSamples < 2 || bakedWSamples > BakedGrid.MAX_SAMPLES)) {
            throw new UserInputException("baked w samples must be 0 (automatic) or 2.." + BakedGrid.MAX_SAMPLES
                    + ", got " + bakedWSamples);
        }
        if (expansion == null) {
            throw new IllegalArgumentException("the Taylor expansion mode is required (AUTO by default)");
        }
    }

    /**
     * The original nine components, with the later knobs at their old behaviour: fixed N (tolerance 0), the fixed
     * window radius, automatic baked-table resolution, the automatic Taylor expansion.
     */
    public BrdfSettings(Variant variant, int highestOrder, int windowRadius, double lambdaMinNm, double lambdaMaxNm,
                        double lambdaStepNm, double sigmaSpatialUm, double refractiveIndex, int pqReplicas) {
        this(variant, highestOrder, windowRadius, lambdaMinNm, lambdaMaxNm, lambdaStepNm, sigmaSpatialUm,
                refractiveIndex, pqReplicas, 0.0, false, 0, 0, TaylorEvaluation.Mode.AUTO);
    }

    /** The thesis' configuration for a variant. */
    public static BrdfSettings thesis(Variant variant) {
        return new BrdfSettings(variant, 30, 1, LAMBDA_MIN_NM, LAMBDA_MAX_NM, 5.0,
                CoherenceWindow.COHERENCE_LENGTH_UM / 4.0, GainFactor.SNAKE_SKIN_REFRACTIVE_INDEX, 0);
    }

    public BrdfSettings withVariant(Variant v) {
        Copy c = new Copy(this);
        c.variant = v;
        return c.build();
    }

    public BrdfSettings withHighestOrder(int n) {
        Copy c = new Copy(this);
        c.highestOrder = n;
        return c.build();
    }

    public BrdfSettings withWindowRadius(int r) {
        Copy c = new Copy(this);
        c.windowRadius = r;
        return c.build();
    }

    public BrdfSettings withLambdaStepNm(double step) {
        Copy c = new Copy(this);
        c.lambdaStepNm = step;
        return c.build();
    }

    public BrdfSettings withLambdaRangeNm(double min, double max) {
        Copy c = new Copy(this);
        c.lambdaMinNm = min;
        c.lambdaMaxNm = max;
        return c.build();
    }

    /** sigma_s of the coherence window (4 sigma_s = the coherence length). */
    public BrdfSettings withSigmaSpatialUm(double sigma) {
        Copy c = new Copy(this);
        c.sigmaSpatialUm = sigma;
        return c.build();
    }

    /** The per-fragment Taylor tolerance (0 = fixed N). */
    public BrdfSettings withTaylorTolerance(double tolerance) {
        Copy c = new Copy(this);
        c.taylorTolerance = tolerance;
        return c.build();
    }

    /** The window radius from sigma_f (true) or the fixed {@code windowRadius} (false). */
    public BrdfSettings withAutomaticWindowRadius(boolean automatic) {
        Copy c = new Copy(this);
        c.automaticWindowRadius = automatic;
        return c.build();
    }

    /** The baked table's samples along u and v, and along w (0 = automatic). */
    public BrdfSettings withBakedSamples(int uvSamples, int wSamples) {
        Copy c = new Copy(this);
        c.bakedUvSamples = uvSamples;
        c.bakedWSamples = wSamples;
        return c.build();
    }

    /** Which Taylor expansion flss/nmm/pq sum (AUTO, PLAIN or CENTRED). */
    public BrdfSettings withExpansion(TaylorEvaluation.Mode mode) {
        Copy c = new Copy(this);
        c.expansion = mode;
        return c.build();
    }

    /** A mutable copy for the with-methods: the one place besides the record header that lists every component. */
    private static final class Copy {
        Variant variant;
        int highestOrder;
        int windowRadius;
        double lambdaMinNm;
        double lambdaMaxNm;
        double lambdaStepNm;
        double sigmaSpatialUm;
        double refractiveIndex;
        int pqReplicas;
        double taylorTolerance;
        boolean automaticWindowRadius;
        int bakedUvSamples;
        int bakedWSamples;
        TaylorEvaluation.Mode expansion;

        Copy(BrdfSettings s) {
            variant = s.variant;
            highestOrder = s.highestOrder;
            windowRadius = s.windowRadius;
            lambdaMinNm = s.lambdaMinNm;
            lambdaMaxNm = s.lambdaMaxNm;
            lambdaStepNm = s.lambdaStepNm;
            sigmaSpatialUm = s.sigmaSpatialUm;
            refractiveIndex = s.refractiveIndex;
            pqReplicas = s.pqReplicas;
            taylorTolerance = s.taylorTolerance;
            automaticWindowRadius = s.automaticWindowRadius;
            bakedUvSamples = s.bakedUvSamples;
            bakedWSamples = s.bakedWSamples;
            expansion = s.expansion;
        }

        BrdfSettings build() {
            return new BrdfSettings(variant, highestOrder, windowRadius, lambdaMinNm, lambdaMaxNm, lambdaStepNm,
                    sigmaSpatialUm, refractiveIndex, pqReplicas, taylorTolerance, automaticWindowRadius,
                    bakedUvSamples, bakedWSamples, expansion);
        }
    }

    /**
     * The window radii for a patch of this extent: the fixed {@code windowRadius} on both axes, or the automatic
     * radius of each axis' sigma_f in texels.
     */
    public WindowRadii windowRadii(double extentXUm, double extentYUm) {
        if (!automaticWindowRadius) {
            return new WindowRadii(windowRadius, windowRadius);
        }
        CoherenceWindow window = coherenceWindow();
        return new WindowRadii(WindowRadii.automatic(window.sigmaTexels(extentXUm)),
                WindowRadii.automatic(window.sigmaTexels(extentYUm)));
    }

    /**
     * The highest Taylor order any fragment can use (only these terms need to be uploaded): N, or with a
     * tolerance the order at which the bound for the largest phase x = (2 pi / lambda_min) 2 max|h| (the worst
     * fragment; 001 sec. 3.3.3) meets the tolerance, if that is below N. Every fragment's own stop order is at
     * most this, since the bound grows with x.
     */
    public int highestOrderNeeded(double maxAbsHeightUm) {
        if (taylorTolerance == 0) {
            return highestOrder;
        }
        double x = TaylorBound.maxPhase(lambdaMinNm, maxAbsHeightUm);
        return Math.min(highestOrder, TaylorBound.stopOrder(x, taylorTolerance, highestOrder));
    }

    public CoherenceWindow coherenceWindow() {
        return new CoherenceWindow(sigmaSpatialUm);
    }

    /** The lambda step this variant actually integrates with (1 nm for the reference). */
    public double effectiveLambdaStepNm() {
        return variant == Variant.REFERENCE ? REFERENCE_STEP_NM : lambdaStepNm;
    }
}
