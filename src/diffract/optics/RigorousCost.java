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
 *
 * <p>A 2-D cell of N = (2 M_x + 1)(2 M_y + 1) harmonics has per distinct slab one eigenproblem of 2N complex unknowns
 * (a real matrix of 4N) and scattering matrices of size 2N; a slab costs about {@link #SECONDS_PER_CUBE_2D} times the
 * cube of 2N (measured on 2 cores: a one-slab solve of 2N = 338 in 3.9 s). A cell of a few heights has few distinct
 * slabs; the estimate counts every layer, an upper bound.
 */
final class RigorousCost {
    /** Seconds per layer and wavelength per (scattering-matrix size)^3, on one core. */
    static final double SECONDS_PER_CUBE = 6.5e-8;
    /** Seconds per 2-D slab and wavelength per (2N)^3, on one core. */
    static final double SECONDS_PER_CUBE_2D = 1.0e-7;
    /** Complex matrices of the scattering-matrix size alive at once in one solve. */
    static final int MATRICES = 40;

    private final int size;
    private final long layerSolves;
    private final int threads;
    private final double secondsPerCube;

    private RigorousCost(int size, long layerSolves, int threads, double secondsPerCube) {
        this.size = size;
        this.layerSolves = layerSolves;
        this.threads = threads;
        this.secondsPerCube = secondsPerCube;
    }

    /** The cost of solving {@code patch} over the band from {@code fromNm} (its widest harmonic set). */
    static RigorousCost of(RigorousPatch patch, BrdfSettings settings, double fromNm) {
        Resolution r = settings.rigorous().resolution();
        int nodes = RigorousOrders.nodesNm(settings.spectral()).length;
        int layers = r.layers() + (r.extrapolate() ? r.layers() / 2 : 0);
        int threads = Math.max(1, Math.min(nodes, Runtime.getRuntime().availableProcessors()));
        if (!patch.oneDimensional()) {
            RigorousPatch.Cost cost = RigorousPatch.twoDimensionalCost(patch.field().widthUm(),
                    patch.field().heightExtentUm(), r, fromNm * 1e-3);
            return new RigorousCost((int) Math.min(Integer.MAX_VALUE, cost.unknowns()), (long) nodes * layers, threads,
                    SECONDS_PER_CUBE_2D);
        }
        int harmonics = 2 * r.maxOrder(patch.profile().periodUm(), fromNm * 1e-3) + 1;
        return new RigorousCost(2 * harmonics, (long) nodes * layers, threads, SECONDS_PER_CUBE);
    }

    /** The heap the solve's matrices take. */
    MemoryEstimate memory() {
        long perThread = 16L * MATRICES * size * size + 8L * 4 * size * size;
        return MemoryEstimate.of(threads + " rigorous solves' matrices of " + size + " x " + size, threads * perThread);
    }

    /** Estimated seconds on this machine (the nodes spread over the cores). */
    double seconds() {
        return secondsPerCube * Math.pow(size, 3) * layerSolves / threads;
    }

    /** "about 40 s" or "about 3 h". */
    String describe() {
        double s = seconds();
        return s < 120 ? String.format(Locale.ROOT, "about %.0f s", Math.max(1, s))
                : s < 7200 ? String.format(Locale.ROOT, "about %.0f min", s / 60)
                : String.format(Locale.ROOT, "about %.1f h", s / 3600);
    }
}
