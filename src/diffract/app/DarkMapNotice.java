package diffract.app;

import diffract.optics.BrdfSettings;
import diffract.optics.windows.CoherenceWindow;
import diffract.optics.windows.WindowRadii;

import java.util.Locale;
import java.util.Optional;

/**
 * Says when a BRDF map comes out black, or its diffraction nearly so, and which option shows it: a picture that
 * is silently black looks like a bug. Two causes are told apart:
 * <ul>
 *   <li>the light is there but the exposure hides it: {@code --exposure auto} maps the brightest diffracted pixel
 *   to white;</li>
 *   <li>no pixel holds any light: the orders are narrower than the map's pixels (point samples, one per pixel)
 *   and the (2R + 1)^2 window around each pixel's lookup holds none of them. A window as wide as the coherence
 *   window's weight ({@code --window-radius auto}) reaches their tails; a larger map samples closer to them.</li>
 * </ul>
 */
final class DarkMapNotice {
    /**
     * Exposed Y below this is black in the PNG: sRGB encodes 3e-4 to 0.0039, one step of 255 (the 8-bit image holds
     * nothing dimmer).
     */
    static final double BLACK_Y = 3e-4;
    /**
     * Diffraction whose brightest pixel is exposed below this is dim: a few faint dots on black (sRGB below 0.54),
     * where the README's pictures show the orders in colour; a note, not a warning (the exposure may be meant).
     */
    static final double DIM_Y = 0.25;
    /** A map whose brightest pixel is below this holds rounding noise only (a double sum of float32 terms). */
    static final double EMPTY_Y = 1e-20;

    private DarkMapNotice() {
    }

    /** What to say: a warning (nothing to see) or a note (dim). */
    record Notice(boolean warning, String text) {
    }

    /**
     * @param brightest           the largest value of the map (Y, or the relative BRDF)
     * @param brightestDiffracted the largest value outside the specular highlight
     * @param exposure            the exposure the PNG was written with
     * @param automaticExposure   whether that exposure was {@code auto}
     * @param settings            the variant's settings (its window)
     * @param extentXUm           the patch's extent along x (sigma_f in texels)
     * @param extentYUm           ... along y
     * @param sizePx              the map's size
     */
    static Optional<Notice> check(double brightest, double brightestDiffracted, double exposure,
                                  boolean automaticExposure, BrdfSettings settings, double extentXUm,
                                  double extentYUm, int sizePx) {
        if (brightest < EMPTY_Y || !Double.isFinite(brightest)) {
            return Optional.of(new Notice(true, String.format(Locale.ROOT, "the map is black: no pixel holds any"
                    + " light (the brightest is %.2g)%s", brightest, emptyReason(settings, extentXUm, extentYUm,
                    sizePx))));
        }
        if (automaticExposure) {
            return Optional.empty(); // auto maps the brightest diffracted pixel (or the highlight) to white
        }
        if (brightest * exposure < BLACK_Y) {
            return Optional.of(new Notice(true, String.format(Locale.ROOT, "the map is black at --exposure %s: its"
                    + " brightest pixel shows %.2g of white; --exposure auto maps the brightest diffracted pixel to"
                    + " white (exposure %.3g)", number(exposure), brightest * exposure,
                    1 / (brightestDiffracted > 0 ? brightestDiffracted : brightest))));
        }
        if (brightestDiffracted > 0 && brightestDiffracted * exposure < DIM_Y) {
            return Optional.of(new Notice(false, String.format(Locale.ROOT, "the diffraction is dim at --exposure %s:"
                    + " its brightest pixel (beside the specular highlight) shows %.2g of white; --exposure auto maps"
                    + " it to white (exposure %.3g)", number(exposure), brightestDiffracted * exposure,
                    1 / brightestDiffracted)));
        }
        return Optional.empty();
    }

    /** Why a map of a windowed variant holds no light, and the option that shows it. */
    private static String emptyReason(BrdfSettings settings, double extentXUm, double extentYUm, int sizePx) {
        if (!settings.variant().readsTerms()) {
            return "; try another light (--theta-i, --phi-i) or a larger --size";
        }
        CoherenceWindow window = settings.coherenceWindow();
        double sigma = Math.max(window.sigmaTexels(extentXUm), window.sigmaTexels(extentYUm));
        double lambdaUm = 0.5 * (settings.spectral().lambdaMinNm() + settings.spectral().lambdaMaxNm()) * 1e-3;
        double texelsPerPixel = 2.0 / sizePx * Math.max(extentXUm, extentYUm) / lambdaUm; // s = u L / lambda
        WindowRadii used = settings.windowRadii(extentXUm, extentYUm);
        int usedRadius = Math.max(used.x(), used.y());
        int automatic = WindowRadii.automatic(sigma);
        String why = String.format(Locale.ROOT, ": its orders are narrower than its pixels (neighbouring pixels look up"
                + " the spectrum %.1f texels apart at %.0f nm, the coherence window's sigma_f is %.2f texels)",
                texelsPerPixel, lambdaUm * 1e3, sigma);
        if (!settings.window().automatic() && automatic > usedRadius) {
            return why + String.format(Locale.ROOT, " and the %d x %d window around each lookup holds none of them;"
                    + " --window-radius auto (%d x %d here) reaches their tails, a larger --size samples closer",
                    2 * usedRadius + 1, 2 * usedRadius + 1, 2 * automatic + 1, 2 * automatic + 1);
        }
        return why + "; a larger --size samples closer to them, a shorter --coherence-length widens them";
    }

    private static String number(double value) {
        return value == Math.rint(value) && Math.abs(value) < 1e9 ? Long.toString((long) value)
                : String.format(Locale.ROOT, "%.4g", value);
    }
}
