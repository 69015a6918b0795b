package diffract.render;

import diffract.jrtr.FloatTextureArray;
import diffract.util.UserInputException;

import java.util.Locale;

/** The command line's names of the Taylor-term texture formats (brdfmap --texture-format, the bench's CSV). */
public final class TermFormats {
    private TermFormats() {
    }

    /** rg32f (exact), rg16f (half precision), rg8 (the thesis' [0, 1]-normalised bytes, 003 eq. 1.1). */
    public static String cliName(FloatTextureArray.Precision precision) {
        switch (precision) {
            case FLOAT16:
                return "rg16f";
            case UNORM8:
                return "rg8";
            default:
                return "rg32f";
        }
    }

    public static FloatTextureArray.Precision parse(String text) {
        for (FloatTextureArray.Precision p : FloatTextureArray.Precision.values()) {
            if (cliName(p).equals(text.trim().toLowerCase(Locale.ROOT))) {
                return p;
            }
        }
        throw new UserInputException("unknown --texture-format '" + text + "': use rg32f, rg16f or rg8");
    }
}
