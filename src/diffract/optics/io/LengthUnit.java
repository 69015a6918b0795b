package diffract.optics.io;

import java.util.Map;
import java.util.OptionalDouble;

/**
 * The length units AFM files name, and their size in micrometres. Gwyddion stores base SI units ("m") and keeps
 * the prefix out of the unit; Igor waves and hand-written files use prefixed ones ("nm", "um"). Both micro signs
 * (U+00B5 and the Greek mu U+03BC) occur.
 */
final class LengthUnit {
    private static final Map<String, Double> MICROMETRES = Map.of(
            "m", 1e6,
            "mm", 1e3,
            "um", 1.0,
            "\u00B5m", 1.0,
            "\u03BCm", 1.0,
            "nm", 1e-3,
            "pm", 1e-6,
            "\u00C5", 1e-4);

    /** The units {@link #micrometres} knows, for messages. */
    static final String KNOWN = "m, mm, um, \u00B5m, nm, pm, \u00C5";

    private LengthUnit() {
    }

    /** The size of one {@code unit} in micrometres, or empty when it is no length unit (deg, V, "" ...). */
    static OptionalDouble micrometres(String unit) {
        Double factor = unit == null ? null : MICROMETRES.get(unit.strip());
        return factor == null ? OptionalDouble.empty() : OptionalDouble.of(factor);
    }

    static boolean isLength(String unit) {
        return micrometres(unit).isPresent();
    }
}
