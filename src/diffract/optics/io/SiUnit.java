package diffract.optics.io;

import java.util.Map;
import java.util.Set;

/**
 * A unit as an instrument writes it ("nm", "nA", "mV", "um") split into an SI base unit and the factor to it, so
 * that every channel's values are in base units ("m", "A", "V"), as Gwyddion keeps them. A unit with no known base
 * (deg, %, counts, "") is kept as written, factor 1.
 */
record SiUnit(String base, double factor) {
    private static final Set<String> BASES = Set.of("m", "A", "V", "N", "Hz", "s", "F", "W", "N/m");
    private static final Map<String, Double> PREFIXES = Map.of(
            "f", 1e-15, "p", 1e-12, "n", 1e-9, "u", 1e-6, "\u00B5", 1e-6, "\u03BC", 1e-6, "m", 1e-3, "k", 1e3,
            "M", 1e6, "G", 1e9);

    static SiUnit of(String written) {
        String unit = written == null ? "" : written.strip().replace("~", "\u00B5");
        if (unit.equals("\u00C5")) {
            return new SiUnit("m", 1e-10);
        }
        if (BASES.contains(unit)) {
            return new SiUnit(unit, 1);
        }
        if (unit.length() > 1) {
            Double prefix = PREFIXES.get(unit.substring(0, 1));
            String rest = unit.substring(1);
            if (prefix != null && BASES.contains(rest)) {
                return new SiUnit(rest, prefix);
            }
        }
        return new SiUnit(unit, 1);
    }
}
