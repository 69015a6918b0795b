package diffract.optics.settings;

import diffract.colour.MirrorNormalisation;

/**
 * The spectral model: which wavelengths the colour integral runs over and how finely the Taylor variants sample
 * it (FLSS and PQ step uniformly; NMM places its own nodes and steps uniformly only near the specular direction).
 * The reference integrates the same range at {@link #REFERENCE_STEP_NM}. The range lies within the CIE 1931 tables
 * (360..830 nm): outside them a wavelength adds no colour.
 *
 * @param lambdaMinNm  the shortest wavelength, also the one the Taylor bounds are taken at
 * @param lambdaMaxNm  the longest wavelength
 * @param lambdaStepNm the uniform step of FLSS and PQ, and NMM's fallback step
 * @param normalisation what a flat mirror holds at D65 white ({@link MirrorNormalisation}): its point-sampled peak
 *                      (the thesis) or the light it reflects (Stam's k^2; radiometric rendering)
 */
public record SpectralSettings(double lambdaMinNm, double lambdaMaxNm, double lambdaStepNm,
                               MirrorNormalisation normalisation) {
    /** The CIE 1931 colour-matching tables' range. */
    public static final double LOWEST_NM = 360;
    public static final double HIGHEST_NM = 830;
    public static final double MAX_STEP_NM = 100;
    /** The visible range of the thesis (003 sec. 1.3.2). */
    public static final double LAMBDA_MIN_NM = 380;
    public static final double LAMBDA_MAX_NM = 780;
    /** The reference integrates at 1 nm. */
    public static final double REFERENCE_STEP_NM = 1.0;

    /** The thesis' normalisation ({@link MirrorNormalisation#PEAK}). */
    public SpectralSettings(double lambdaMinNm, double lambdaMaxNm, double lambdaStepNm) {
        this(lambdaMinNm, lambdaMaxNm, lambdaStepNm, MirrorNormalisation.PEAK);
    }

    public SpectralSettings {
        if (normalisation == null) {
            throw new IllegalArgumentException("the mirror's normalisation is missing");
        }
        InvalidSettingException.requireWithin(Quantity.LAMBDA_MIN, lambdaMinNm, LOWEST_NM, HIGHEST_NM);
        InvalidSettingException.requireWithin(Quantity.LAMBDA_MAX, lambdaMaxNm, LOWEST_NM, HIGHEST_NM);
        if (!(lambdaMaxNm > lambdaMinNm)) {
            throw new InvalidSettingException(Quantity.LAMBDA_MAX, "the longest wavelength must exceed the shortest, got "
                    + InvalidSettingException.number(lambdaMinNm) + " and " + InvalidSettingException.number(lambdaMaxNm)
                    + " nm");
        }
        if (!(lambdaStepNm > 0 && lambdaStepNm <= MAX_STEP_NM)) {
            throw new InvalidSettingException(Quantity.LAMBDA_STEP, "the wavelength step must be in (0, "
                    + InvalidSettingException.number(MAX_STEP_NM) + "] nm, got " + lambdaStepNm);
        }
    }

    /** The same band and step with another normalisation. */
    public SpectralSettings withNormalisation(MirrorNormalisation n) {
        return new SpectralSettings(lambdaMinNm, lambdaMaxNm, lambdaStepNm, n);
    }

    /** 380..780 nm in 5 nm steps (003 sec. 1.3.2). */
    public static SpectralSettings thesis() {
        return new SpectralSettings(LAMBDA_MIN_NM, LAMBDA_MAX_NM, 5.0);
    }
}
