package diffract.render;

import diffract.jrtr.OffscreenTarget;
import diffract.util.Reporter;

import java.util.Locale;

/**
 * Pixels left short: where the GL ended the lobes shader's loops before their work was done, so that the pixel misses
 * lobes and is too dark. Mesa's llvmpipe ends a SIMD group's loops after 65535 iterations, silently; the shader
 * notices that its march or its wavelength nodes did not finish (lobes_spectrum.glsl) and its fragment writes alpha 0
 * there, in a BRDF map, a baked table's bake and on a scene's surfaces alike (diffraction_main.glsl's
 * {@code leftOutAlpha}). A reader of such frames counts them here and says so once, naming what draws them whole,
 * instead of leaving a darker picture unexplained.
 */
public final class ShortPixels {
    private long pixels;
    private long shortPixels;

    /** Counts the pixels of alpha 0 of {@code rgba} (4 floats a pixel). */
    public ShortPixels countIn(float[] rgba) {
        for (int i = 3; i < rgba.length; i += 4) {
            if (rgba[i] == 0) {
                shortPixels++;
            }
        }
        pixels += rgba.length / 4;
        return this;
    }

    /** The RGB of {@code rgba} (4 floats a pixel, in its order), counting its pixels of alpha 0. */
    public float[] rgbOf(float[] rgba) {
        countIn(rgba);
        return OffscreenTarget.dropAlpha(rgba);
    }

    /** The pixels of alpha 0 counted so far. */
    public long count() {
        return shortPixels;
    }

    /**
     * Warns through {@code reporter} when pixels were left short: {@code what} names them ("pixels of the frame"),
     * {@code renderer} the GL, {@code remedy} what draws them whole.
     */
    public void warnIfAny(Reporter reporter, String what, String renderer, String remedy) {
        if (shortPixels > 0) {
            reporter.warn(warning(shortPixels, pixels, what, renderer, remedy));
        }
    }

    /** The one wording of the warning, for maps, tables and frames: {@code count} of {@code total} left short. */
    public static String warning(long count, long total, String what, String renderer, String remedy) {
        return String.format(Locale.ROOT, "%d of the %d %s reach more lobes than %s lets one fragment sum (its "
                + "loops were ended early; Mesa's llvmpipe ends them after 65535 iterations): they miss lobes and are "
                + "too dark; %s", count, total, what, renderer, remedy);
    }
}
