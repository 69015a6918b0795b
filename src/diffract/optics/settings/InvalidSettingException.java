package diffract.optics.settings;

import diffract.util.UserInputException;

/**
 * A value of one {@link Quantity} that cannot be used: the message names the quantity in words and the fix; the
 * command line prefixes the option that gives it, the scene reader the key.
 */
public final class InvalidSettingException extends UserInputException {
    private static final long serialVersionUID = 1L;

    private final Quantity quantity;

    public InvalidSettingException(Quantity quantity, String message) {
        super(message);
        this.quantity = quantity;
    }

    public Quantity quantity() {
        return quantity;
    }

    /** Throws unless {@code lowest <= value <= highest}: "the wavelength step must be in [a, b], got v". */
    public static void requireWithin(Quantity quantity, double value, double lowest, double highest) {
        if (!(value >= lowest && value <= highest)) {
            throw new InvalidSettingException(quantity, quantity.words() + " must be in [" + number(lowest)
                    + ", " + number(highest) + "], got " + number(value));
        }
    }

    /** Whole numbers and plain decimals without trailing zeros. */
    public static String number(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }
}
