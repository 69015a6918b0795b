package diffract.optics.windows;

import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;

import java.util.Locale;

/**
 * Where the Gaussian coherence window sits on the patch (docs/design/theory.md, "The window averaged over its position").
 *
 * <p>The thesis reads the DFT through one window at a fixed place, P(s) = sum_m G(s - m) T_m (004 eq.
 * {@code finalexpression}): the window centred where the DFT's phases are zero. A window centred at x0 instead
 * multiplies T_m by exp(2 pi i m . x0 / L) (the shift theorem), so |P|^2 carries, for every pair of texels, the
 * phase exp(2 pi i (m - m') . x0 / L). A pixel on a surface wider than a coherence area (a snake's skin, a scan
 * wider than 4 sigma_s) or a light wider than a lobe sees many coherence areas at once: the average over x0 of the
 * DFT's periodic patch. Over one period every pair's phase averages to zero, exactly, and what is left is the
 * diagonal sum
 * <pre>
 *   &lt;|P(s)|^2&gt;_x0 = sum_m G(s - m)^2 |T_m|^2,
 * </pre>
 * which does not change when the scan is shifted cyclically. For patches narrower than the window the two agree to
 * the weight of the nearest pair, exp(-1 / (4 sigma^2)) with sigma = sigma_f L texels (5e-12 for a 10 um patch at
 * 65 um); for a scan as wide as the window they differ, and only the average is independent of where the scan was cut.
 */
public enum WindowPlacement {
    /** The BRDF averaged over the window's position: sum_m G^2 |T_m|^2 (the default, the physics of a pixel). */
    AVERAGED,
    /** One window at the DFT's origin: |sum_m G T_m|^2, as the thesis (for comparisons). */
    FIXED,
    /**
     * The window at the surface point a pixel sees, averaged over the pixel's footprint on the skin
     * ({@link LocalWindow}): FIXED where the footprint is a point, AVERAGED where it covers the scan, spatially varying
     * glints between. Needs a surface point, so only a mesh's FLSS and NMM draw it.
     */
    LOCAL;

    /** averaged, fixed: the name on the command line and in scene files. */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The placement of a {@link #label()} (any case). */
    public static WindowPlacement parse(String text) {
        for (WindowPlacement p : values()) {
            if (p.label().equalsIgnoreCase(text.trim())) {
                return p;
            }
        }
        throw new InvalidSettingException(Quantity.WINDOW_PLACEMENT, "unknown window placement '" + text
                + "': use averaged (the BRDF averaged over where the coherence window sits, the default) or fixed"
                + " (one window at the DFT's origin, as the thesis) or local (the window under each surface point, averaged"
                + " over the pixel's footprint on the skin)");
    }
}
