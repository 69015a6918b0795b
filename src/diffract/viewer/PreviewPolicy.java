package diffract.viewer;

import diffract.optics.BrdfSettings;
import diffract.optics.settings.PixelFilter;
import diffract.optics.Methods;

/**
 * The settings of the viewer's preview, the cheap first pass of each refinement ({@link RefiningRenderer}): the
 * one place that decides what "cheap" means. Settings that are cheap per fragment already (the baked table once it
 * is baked: one lookup) are their own preview. Anything else is previewed by the fallback method ({@link Methods.Role#FALLBACK}, FLSS) with the same terms (so the same
 * expansion) on the centre texel of the coherence window ({@value #WINDOW_RADIUS}: one texel instead of (2R+1)^2,
 * exact where sigma_f is well under a texel, as for long coherence lengths) and wavelengths at least
 * {@value #LAMBDA_STEP_NM} nm apart ({@code 380..780} in 11 samples): on llvmpipe about 1/10 of the thesis'
 * configuration's cost per pixel. The orders land where the configured settings put them; their colours are
 * coarser and the finer passes replace them. FLSS samples the light at its centre and each pixel at its centre, so
 * the preview draws a point light into point-sampled pixels.
 */
public final class PreviewPolicy {
    /** The preview reads one texel of the coherence window. */
    public static final int WINDOW_RADIUS = 0;
    /** The preview's wavelength step, or the configured one where it is coarser. */
    public static final double LAMBDA_STEP_NM = 40;

    private PreviewPolicy() {
    }

    /**
     * The preview of a frame drawn with {@code drawable} (a state's {@link ViewerState#drawableSettings()});
     * {@code bakedTableReady} says whether the baked table of those settings is at hand (only then is the baked
     * variant cheap: until it is baked, the configured frame cannot be drawn at all).
     */
    public static BrdfSettings settings(BrdfSettings drawable, boolean bakedTableReady) {
        if (drawable.variant().drawsTable() && bakedTableReady) {
            return drawable;
        }
        return drawable.with(b -> b.drawnBy(Methods.Role.FALLBACK.method()).windowRadius(WINDOW_RADIUS)
                .lambdaStepNm(Math.max(LAMBDA_STEP_NM, drawable.spectral().lambdaStepNm())).lightSizeDeg(0)
                .pixelFilter(PixelFilter.POINT));
    }
}
