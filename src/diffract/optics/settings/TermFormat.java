package diffract.optics.settings;

import java.util.Locale;

/** How the Taylor terms are stored on the GPU. */
public enum TermFormat {
    /** float32 (Re, Im): exactly the precomputed values. */
    RG32F,
    /** Half precision: 11 significant bits, values below 6e-8 flushed to 0; an option for memory, not accuracy. */
    RG16F,
    /** The thesis' [0, 1]-normalised bytes with per-term extrema (003 eq. 1.1); the series around 0 only. */
    RG8;

    /** rg32f, rg16f, rg8. */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }
}
