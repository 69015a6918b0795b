package diffract.optics;

import java.util.Locale;

/**
 * How the BRDF is evaluated: the exact reference, one of the thesis' three shader approximations, a baked table of
 * FLSS, or the filtered lobes method. A new variant is a constant here, its CPU spectrum in
 * {@link DiffractionBrdf#create} (or {@link #runsOnCpu} false), its fragment shader
 * {@code shaders/diffraction/<name>.frag}, and, where it ignores a swept axis, a line in the bench's
 * {@code SweepPlan.IGNORED_AXES}.
 */
public enum Variant {
    /** exp(i k w h) exactly, window until weights < 1e-12, lambda at 1 nm: the yardstick. */
    REFERENCE,
    /** Full lambda-space sampling (003 Algorithm 3): uniform lambda steps, N Taylor terms, Gaussian window. */
    FLSS,
    /** n_min/n_max (003 section 1.5.2): only the wavelengths that land on DFT texel centres, with the Jacobian. */
    NMM,
    /** Periodic replication and sinc interpolation (003 section 1.5.3, 004 "PQ factors"). */
    PQ,
    /**
     * FLSS baked into a 3-D table XYZ(u, v, w) once per patch and settings, looked up trilinearly per fragment
     * (after Dhillon and Ghosh 2016, Toisoul and Ghosh 2017). GPU only.
     */
    BAKED,
    /**
     * The windowed spectrum's Gaussian lobes, each widened by the pixel's footprint and the light and integrated
     * over wavelength by a rule fitted to its passage (LobeSpectrum, lobes.frag): valid at the true coherence length.
     */
    LOBES;

    /** Whether DiffractionBrdf evaluates it on the CPU (the baked table exists on the GPU only). */
    public boolean runsOnCpu() {
        return this != BAKED;
    }

    /**
     * Whether it averages over an extended light's directions (the lobes method and its baked table); the reference
     * does too but draws no scenes, and the others sample the light at its centre.
     */
    public boolean filtersLight() {
        return this == LOBES || this == BAKED;
    }

    /** Whether it runs as a GPU shader (all but the reference). */
    public boolean runsOnGpu() {
        return this != REFERENCE;
    }

    /** reference, flss, nmm, pq, baked, lobes: the name on the command line, in scene files and in tables. */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The variant of a {@link #label()} (any case). */
    public static Variant parse(String text) {
        for (Variant v : values()) {
            if (v.label().equalsIgnoreCase(text.trim())) {
                return v;
            }
        }
        throw new InvalidSettingException(Quantity.VARIANT, "unknown variant '" + text
                + "': use reference, flss, nmm, pq, baked or lobes");
    }
}
