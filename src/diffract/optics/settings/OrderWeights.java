package diffract.optics.settings;

import java.util.Locale;

/**
 * What weighs the lobes method's orders: the scalar model (|T_m|^2 times the gain model, the default), or the
 * patch's orders from Maxwell's equations ({@code OrderCorrection}: each lobe times its order's ratio
 * of rigorous to scalar efficiency, from a table solved once per patch and kept in the disk cache; a 1-D patch's own
 * orders, a 2-D snake patch's through its average ridge). The reference, FLSS, NMM and PQ draw the scalar model; the
 * rigorous method is Maxwell's equations throughout.
 */
public enum OrderWeights {
    SCALAR,
    RIGOROUS;

    /** scalar, rigorous: the name on the command line and in scene files. */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The weights of a {@link #label()} (any case). */
    public static OrderWeights parse(String text) {
        for (OrderWeights w : values()) {
            if (w.label().equalsIgnoreCase(text.trim())) {
                return w;
            }
        }
        throw new InvalidSettingException(Quantity.ORDERS, "unknown orders '" + text + "': use scalar (the scalar "
                + "model's) or rigorous (the patch's orders from Maxwell's equations, for the lobes method)");
    }
}
