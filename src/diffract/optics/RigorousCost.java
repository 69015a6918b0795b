package diffract.optics;

import diffract.optics.rigorous.Resolution;
import diffract.util.MemoryEstimate;

import java.util.Locale;

/**
 * What the rigorous method's solve of a patch costs, estimated before the work: the heap its matrices take (per
 * worker thread, the wavelength nodes being solved in parallel) and the time, from the size of the eigenproblems.
 *
 * <p>A 1-D grating of 2M + 1 harmonics has per layer two eigenproblems of size 2M + 1 (decomposed as real matrices of
 * twice the size) and scattering matrices of size 2 (2M + 1); a layer costs about {@link #SECONDS_PER_CUBE} times the
 * cube of the scattering matrices' size (measured on this project's 2-core machine: 35 ms per layer at M = 20).
 */
final class RigorousCost {
    /** Seconds per layer and wavelength per (scattering-matrix size)^3, on one core. */
    static final double SECONDS_PER_CUBE = 6.5e-8;
    /** Complex matrices of the scattering-matrix size alive at once in one solve. */
    static final int MATRICES = 40;

    private final int size;
    private final long layerSolves;
    private final int threads;

    private RigorousCost(int size, long layerSolves, int threads) {
        this.size = size;
        this.layerSolves = layerSolves;
        this.threads = threads;
    }

    /** The cost of solving {@code patch} over the band from {@code fromNm} (its widest harmonic set). */
    static RigorousCost of(RigorousPatch patch, BrdfSettings settings, double fromNm) {
        Resolution r = settings.rigorous().resolution();
        int harmonics = 2 * r.maxOrder(patch.profile().periodUm(), fromNm * 1e-3) + 1;
        int nodes = RigorousOrders.nodesNm(settings.spectral()).length;
        int layers = r.layers() + (r.extrapolate() ? r.layers() / 2 : 0);
        return new RigorousCost(2 * harmonics, (long) nodes * layers,
                Math.max(1, Math.min(nodes, Runtime.getRuntime().availableProcessors())));
    }

    /** The heap the solve's matrices take. */
    MemoryEstimate memory() {
        long perThread = 16L * MATRICES * size * size + 8L * 4 * size * size;
        return MemoryEstimate.of(threads + " rigorous solves' matrices of " + size + " x " + size, threads * perThread);
    }

    /** Estimated seconds on this machine (the nodes spread over the cores). */
    double seconds() {
        return SECONDS_PER_CUBE * Math.pow(size, 3) * layerSolves / threads;
    }

    /** "about 40 s" or "about 3 h". */
    String describe() {
        double s = seconds();
        return s < 120 ? String.format(Locale.ROOT, "about %.0f s", Math.max(1, s))
                : s < 7200 ? String.format(Locale.ROOT, "about %.0f min", s / 60)
                : String.format(Locale.ROOT, "about %.1f h", s / 3600);
    }
}
