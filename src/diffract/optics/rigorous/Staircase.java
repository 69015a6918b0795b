package diffract.optics.rigorous;

import java.util.ArrayList;
import java.util.List;

/**
 * A relief cut into slabs of equal thickness (the staircase approximation of the Fourier modal method): slab j of M,
 * counted from the top, holds the material wherever the profile rises above the middle of its height range,
 * depth (1 - (j + 1/2) / M). The midpoint rule errs by O(1 / M^2) in the relief's area per slab; the efficiencies
 * converge in M as {@link FourierModalMethod}'s users check by doubling it.
 */
public final class Staircase {
    /** Scan points per period before the crossings are refined by bisection. */
    static final int SCAN_POINTS = 8192;

    private Staircase() {
    }

    /** The {@code layers} slabs of the profile, top first. */
    public static List<Slab> of(Profile profile, int layers) {
        if (layers < 1) {
            throw new IllegalArgumentException("a staircase needs at least one layer, got " + layers);
        }
        List<Slab> slabs = new ArrayList<>(layers);
        if (profile.depthUm() == 0) {
            return slabs;
        }
        double[] samples = new double[SCAN_POINTS + 1];
        for (int i = 0; i <= SCAN_POINTS; i++) {
            samples[i] = profile.at(i / (double) SCAN_POINTS);
        }
        samples[SCAN_POINTS] = samples[0];
        for (int j = 0; j < layers; j++) {
            double level = profile.depthUm() * (1 - (j + 0.5) / layers);
            slabs.add(new Slab(profile.depthUm() / layers, above(profile, samples, level)));
        }
        return slabs;
    }

    /** The intervals of t in [0, 1] where h(t) &gt; level, as {@link Slab#edges}. */
    static double[] above(Profile profile, double[] samples, double level) {
        List<Double> edges = new ArrayList<>();
        boolean inside = samples[0] > level;
        if (inside) {
            edges.add(0.0);
        }
        for (int i = 0; i < SCAN_POINTS; i++) {
            boolean next = samples[i + 1] > level;
            if (next != inside) {
                edges.add(crossing(profile, i / (double) SCAN_POINTS, (i + 1) / (double) SCAN_POINTS, level, inside));
                inside = next;
            }
        }
        if (inside) {
            edges.add(1.0);
        }
        double[] out = new double[edges.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = edges.get(i);
        }
        // bisection can put two crossings of one scan step in the wrong order by an ulp
        for (int i = 1; i < out.length; i++) {
            out[i] = Math.max(out[i], out[i - 1]);
        }
        return out;
    }

    /** The t in [lo, hi] where h crosses the level, by bisection to double precision. */
    private static double crossing(Profile profile, double lo, double hi, double level, boolean aboveAtLo) {
        for (int k = 0; k < 60 && hi - lo > 1e-16; k++) {
            double mid = 0.5 * (lo + hi);
            if ((profile.at(mid) > level) == aboveAtLo) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return 0.5 * (lo + hi);
    }
}
