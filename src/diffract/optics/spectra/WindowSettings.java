package diffract.optics.spectra;

import diffract.optics.patches.ScanTiling;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;
import diffract.optics.windows.CoherenceWindow;
import diffract.optics.windows.WindowPlacement;
import diffract.optics.windows.WindowRadii;

/**
 * How P is read between the DFT texels (003 eq. 1.9 and sec. 1.5.3): the Gaussian coherence window's
 * neighbourhood (FLSS, NMM, and the baked table's FLSS), or PQ's periodic replication, and where the window sits on
 * the patch ({@link WindowPlacement}: averaged over its position, or fixed at the DFT's origin as the thesis).
 *
 * @param radius     R texels: a (2R + 1)^2 neighbourhood, when not {@code automatic}
 * @param automatic  the radius per axis follows sigma_f in texels ({@link WindowRadii#automatic}) instead
 * @param pqReplicas PQ's replicas per axis; 0 = enough to span the coherence length
 * @param placement  the BRDF averaged over the window's position (every method sums texels' powers), or one window
 *                   at the DFT's origin (every method sums complex amplitudes, then squares), or under each
 *                   surface point of a mesh ({@link WindowPlacement#LOCAL})
 * @param tiling     how the scan lies on a mesh's texture coordinates, for the local window
 */
public record WindowSettings(int radius, boolean automatic, int pqReplicas, WindowPlacement placement,
                             ScanTiling tiling) {
    /**
     * The largest fixed radius, a 33 x 33 window: sigma_f grows with the patch (2 texels for a 200 um patch at the
     * thesis' coherence), and the automatic radius stops at {@link WindowRadii#MAX_AUTOMATIC} for cost.
     */
    public static final int MAX_RADIUS = 16;
    public static final int MAX_PQ_REPLICAS = 100;

    public WindowSettings {
        if (radius < 0 || radius > MAX_RADIUS) {
            throw new InvalidSettingException(Quantity.WINDOW_RADIUS, Quantity.WINDOW_RADIUS.words()
                    + " must be in 0.." + MAX_RADIUS + " texels, got " + radius);
        }
        if (pqReplicas < 0 || pqReplicas > MAX_PQ_REPLICAS) {
            throw new InvalidSettingException(Quantity.PQ_REPLICAS, Quantity.PQ_REPLICAS.words()
                    + " must be in 0.." + MAX_PQ_REPLICAS + " (0 = span the coherence length), got " + pqReplicas);
        }
        if (placement == null || tiling == null) {
            throw new NullPointerException("the window's placement and the scan's tiling are required");
        }
    }

    /** No tiling: the averaged and fixed windows need none. */
    public WindowSettings(int radius, boolean automatic, int pqReplicas, WindowPlacement placement) {
        this(radius, automatic, pqReplicas, placement, ScanTiling.NONE);
    }

    /**
     * The thesis' 3 x 3 window and automatic PQ replicas, averaged over the window's position (the thesis' own model,
     * one window at the DFT's origin, is {@link WindowPlacement#FIXED}; the two agree for patches narrower than the
     * window).
     */
    public static WindowSettings thesis() {
        return new WindowSettings(1, false, 0, WindowPlacement.AVERAGED);
    }

    /** The radii per axis for a patch of this extent under this coherence window. */
    public WindowRadii radii(CoherenceWindow window, double extentXUm, double extentYUm) {
        if (!automatic) {
            return new WindowRadii(radius, radius);
        }
        return new WindowRadii(WindowRadii.automatic(window.sigmaTexels(extentXUm)),
                WindowRadii.automatic(window.sigmaTexels(extentYUm)));
    }

    /** PQ's replicas along an axis of this extent: the fixed count, or enough to span the coherence length. */
    public int replicas(CoherenceWindow window, double extentUm) {
        return pqReplicas > 0 ? pqReplicas : TaylorSincSpectrum.replicasForCoherence(window, extentUm);
    }
}
