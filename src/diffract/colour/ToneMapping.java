package diffract.colour;

import java.util.Locale;

/**
 * From linear scene light (linear sRGB, key light = 1) to displayable linear sRGB in [0, 1], before the sRGB
 * encoding: an exposure in photographic stops (x 2^stops) and one of three operators. The GLSL twin is
 * {@code shaders/lighting/tone_mapping.glsl}; this class is its specification.
 *
 * <ul>
 *   <li>{@link Operator#CLIP}: each channel clipped to [0, 1] (what a plain sRGB encoding does);</li>
 *   <li>{@link Operator#REINHARD}: E. Reinhard et al., "Photographic Tone Reproduction for Digital Images",
 *       SIGGRAPH 2002, eq. 4, on luminance Y (Rec. 709 weights): Y_d = Y (1 + Y / Y_white^2) / (1 + Y), the colour
 *       scaled by Y_d / Y so hue and saturation are kept; Y_white maps to 1; a colour whose largest channel then
 *       exceeds 1 is scaled down to it (its hue kept) instead of clipped per channel;</li>
 *   <li>{@link Operator#ACES}: K. Narkowicz's fit of the ACES filmic curve (2015), per channel,
 *       x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14), which desaturates highlights as film does.</li>
 * </ul>
 *
 * @param whiteLuminance REINHARD: the luminance (after exposure) shown as white; ignored by the others
 */
public record ToneMapping(Operator operator, double exposureStops, double whiteLuminance) {
    public enum Operator {
        CLIP, REINHARD, ACES;

        /** The scene-file and command-line spelling. */
        public String sceneName() {
            return name().toLowerCase(Locale.ROOT);
        }

        public static Operator parse(String text) {
            return valueOf(text.trim().toUpperCase(Locale.ROOT));
        }
    }

    public ToneMapping {
        if (operator == null || !Double.isFinite(exposureStops) || !(whiteLuminance > 0)) {
            throw new IllegalArgumentException("tone mapping needs an operator, finite stops and a white > 0");
        }
    }

    /** Today's display path: no exposure change, channels clipped. */
    public static ToneMapping clip() {
        return new ToneMapping(Operator.CLIP, 0, 1);
    }

    /** The exposure factor 2^stops. */
    public double exposureScale() {
        return Math.pow(2, exposureStops);
    }

    /** Displayable linear sRGB in [0, 1] of a linear sRGB colour. */
    public double[] apply(double[] linear) {
        double s = exposureScale();
        double r = Math.max(0, linear[0] * s);
        double g = Math.max(0, linear[1] * s);
        double b = Math.max(0, linear[2] * s);
        switch (operator) {
            case REINHARD: {
                double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
                if (y <= 0) {
                    return new double[] {0, 0, 0};
                }
                double yd = y * (1 + y / (whiteLuminance * whiteLuminance)) / (1 + y);
                double k = yd / y;
                double[] out = {r * k, g * k, b * k};
                double max = Math.max(out[0], Math.max(out[1], out[2]));
                if (max > 1) {
                    out[0] /= max;
                    out[1] /= max;
                    out[2] /= max;
                }
                return out;
            }
            case ACES:
                return new double[] {aces(r), aces(g), aces(b)};
            default:
                return new double[] {Math.min(1, r), Math.min(1, g), Math.min(1, b)};
        }
    }

    static double aces(double x) {
        return Math.min(1, Math.max(0, x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14)));
    }
}
