package diffract.optics.settings;

import java.util.Locale;

/** What one BRDF-map pixel shows (docs/design/filtering.md). */
public enum PixelFilter {
    /** The BRDF at the pixel's centre direction, the thesis' way (aliases orders narrower than a pixel). */
    POINT,
    /** The average of the BRDF over the pixel's square in the projected (x, y) plane: the definition. */
    BOX;

    /** point, box: the name on the command line and in scene files. */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The filter of a {@link #label()} (any case). */
    public static PixelFilter parse(String text) {
        for (PixelFilter f : values()) {
            if (f.label().equalsIgnoreCase(text.trim())) {
                return f;
            }
        }
        throw new InvalidSettingException(Quantity.PIXEL_FILTER, "unknown pixel filter '" + text
                + "': use box (each pixel's average, the default) or point (its centre, as the thesis)");
    }
}
