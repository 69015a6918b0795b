package diffract.optics.settings;

/**
 * The quantities a user gives, by a command-line option or a scene-file key. Messages about one of them name the
 * quantity in words ({@link #words()}); the command line and the scene reader each say where the user gives it
 * ({@code --terms}, {@code material.taylorTerms}), so the optics never speak of flags or keys.
 */
public enum Quantity {
    VARIANT("the variant"),
    HIGHEST_ORDER("the highest Taylor order N"),
    ORDER_TOLERANCE("the tolerance that chooses N"),
    TAYLOR_TOLERANCE("the per-lookup Taylor tolerance"),
    EXPANSION("the Taylor expansion"),
    WINDOW_RADIUS("the window radius R"),
    WINDOW_PLACEMENT("the coherence window's placement"),
    SCAN_TILING("the micrometres of skin per unit of texture coordinates"),
    PQ_REPLICAS("the PQ replicas per axis"),
    LAMBDA_MIN("the shortest wavelength"),
    LAMBDA_MAX("the longest wavelength"),
    LAMBDA_STEP("the wavelength step"),
    MONOCHROMATIC_LAMBDA("the wavelength of a monochromatic map"),
    COHERENCE_LENGTH("the coherence length 4 sigma_s"),
    REFRACTIVE_INDEX("the refractive index"),
    HARMONICS("the rigorous method's highest harmonic"),
    LAYERS("the rigorous method's staircase layers"),
    POLARISATION("the light's polarisation"),
    ORDERS("the lobes method's orders"),
    LIGHT_SIZE("the light's angular diameter"),
    LIGHT_PROFILE("the light's profile"),
    GAIN("the gain model"),
    PIXEL_FILTER("the pixel filter"),
    LOBE_QUADRATURE("the lobes' quadrature"),
    TERM_FORMAT("the term texture format"),
    BAKED_SAMPLES("the baked table's samples"),
    MAX_HEIGHT("the height of the brightest grey value"),
    PIXEL_SIZE("the pixel size"),
    CHANNEL("the channel"),
    TERMS_HEIGHT_UNIT("the height unit of thesis-format terms");

    private final String words;

    Quantity(String words) {
        this.words = words;
    }

    /** The quantity in words, e.g. "the highest Taylor order N". */
    public String words() {
        return words;
    }
}
