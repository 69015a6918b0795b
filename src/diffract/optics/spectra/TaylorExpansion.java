package diffract.optics.spectra;

/** Which Taylor expansion of exp(i k w h) FLSS, NMM and PQ sum ({@code TaylorEvaluation}). */
public enum TaylorExpansion {
    /** The thesis' series around 0 where the patch lets it reach {@link Float32Cancellation#TOLERANCE_IN_P}, else centred. */
    AUTO,
    /** Always the thesis' series around 0 (its output is unchanged, rounding noise included). */
    PLAIN,
    /** Always the phase-centred expansion ({@link PhaseCentres}). */
    CENTRED
}
