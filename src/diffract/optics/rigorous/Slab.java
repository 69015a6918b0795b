package diffract.optics.rigorous;

import java.util.Arrays;

/**
 * One layer of a 1-D grating's staircase: uniform through its thickness, the material over some intervals of the
 * period and air over the rest.
 *
 * @param thicknessUm the layer's thickness, um
 * @param edges       the material's intervals as fractions of the period, [a0, b0, a1, b1, ...] with
 *                    0 &lt;= a0 &lt; b0 &lt;= a1 &lt; ... &lt;= 1; empty: all air
 */
public record Slab(double thicknessUm, double[] edges) {
    public Slab {
        if (!(thicknessUm > 0) || !Double.isFinite(thicknessUm)) {
            throw new IllegalArgumentException("a slab's thickness must be > 0 um, got " + thicknessUm);
        }
        if (edges.length % 2 != 0) {
            throw new IllegalArgumentException("a slab's edges come in pairs, got " + edges.length);
        }
        double previous = 0;
        for (double e : edges) {
            if (!(e >= previous && e <= 1)) {
                throw new IllegalArgumentException("a slab's edges rise within [0, 1]: " + Arrays.toString(edges));
            }
            previous = e;
        }
        edges = edges.clone();
    }

    /** A slab of material over the whole period. */
    public static Slab solid(double thicknessUm) {
        return new Slab(thicknessUm, new double[] {0, 1});
    }

    /** The fraction of the period the material fills. */
    public double fill() {
        double sum = 0;
        for (int i = 0; i < edges.length; i += 2) {
            sum += edges[i + 1] - edges[i];
        }
        return sum;
    }

    /** Whether the slab is all air or all material (its modes are plane waves). */
    public boolean uniform() {
        double f = fill();
        return f <= 0 || f >= 1;
    }

    /**
     * The Fourier coefficient chi_n = integral over a period of chi(t) exp(-2 pi i n t) dt of the material's
     * indicator, into {@code out} as (Re, Im): for each interval (sin 2 pi n b - sin 2 pi n a
     * + i (cos 2 pi n b - cos 2 pi n a)) / (2 pi n), and its length at n = 0. The relief is then
     * epsilon(t) = sum_n epsilon_n exp(2 pi i n t) with epsilon_n = delta_n0 + (epsilon_material - 1) chi_n.
     */
    public void fourier(int n, double[] out) {
        if (n == 0) {
            out[0] = fill();
            out[1] = 0;
            return;
        }
        double theta = 2 * Math.PI * n;
        double re = 0;
        double im = 0;
        for (int i = 0; i < edges.length; i += 2) {
            double a = theta * edges[i];
            double b = theta * edges[i + 1];
            re += Math.sin(b) - Math.sin(a);
            im += Math.cos(b) - Math.cos(a);
        }
        out[0] = re / theta;
        out[1] = im / theta;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Slab s && s.thicknessUm == thicknessUm && Arrays.equals(s.edges, edges);
    }

    @Override
    public int hashCode() {
        return 31 * Double.hashCode(thicknessUm) + Arrays.hashCode(edges);
    }

    @Override
    public String toString() {
        return "Slab[" + thicknessUm + " um, " + Arrays.toString(edges) + "]";
    }

    @Override
    public double[] edges() {
        return edges.clone();
    }
}
