package diffract.optics.numerics;

import java.util.PriorityQueue;
import java.util.function.DoubleFunction;

/**
 * Globally adaptive Gauss-Kronrod quadrature (7-point Gauss, 15-point Kronrod, the rule of QUADPACK's QK15; the
 * strategy of QUADPACK's QAG) of a vector-valued function: the interval whose Kronrod and Gauss estimates differ most
 * is halved until the sum of those differences over all intervals, for every component, is at most
 * {@code relativeTolerance} times the largest component of the total (or {@code absoluteFloor}). |K15 - G7|
 * bounds the error of the 7-point rule; the 15-point estimate that is summed is far more accurate. The filtered
 * reference's wavelength and light integrals use it.
 */
public final class GaussKronrod {
    private static final double[] NODES = {
        0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
        0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
        0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
        0.207784955007898467600689403773245, 0.0,
    };
    private static final double[] KRONROD_WEIGHTS = {
        0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
        0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
        0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
        0.204432940075298892414161999234649, 0.209482141084727828012999174891714,
    };
    private static final double[] GAUSS_WEIGHTS = {
        0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
        0.381830050505118944950369775488975, 0.417959183673469387755102040816327,
    };
    /** The most intervals one integral is split into (a guard; smooth integrands need a few dozen). */
    static final int MAX_INTERVALS = 4000;

    private GaussKronrod() {
    }

    private record Piece(double lo, double hi, double[] kronrod, double error) {
    }

    /**
     * The integral of f over [a, b].
     *
     * @param dimension the length of the arrays f returns
     */
    public static double[] integrate(DoubleFunction<double[]> f, int dimension, double a, double b,
                                     double relativeTolerance, double absoluteFloor) {
        double[] total = new double[dimension];
        if (!(b > a)) {
            return total;
        }
        PriorityQueue<Piece> pieces = new PriorityQueue<>((p, q) -> Double.compare(q.error, p.error));
        Piece first = rule(f, a, b, dimension);
        pieces.add(first);
        double[] sum = first.kronrod.clone();
        double errorSum = first.error;
        while (pieces.size() < MAX_INTERVALS) {
            double largest = 0;
            for (double v : sum) {
                largest = Math.max(largest, Math.abs(v));
            }
            if (errorSum <= Math.max(relativeTolerance * largest, absoluteFloor)) {
                break;
            }
            Piece worst = pieces.poll();
            double mid = 0.5 * (worst.lo + worst.hi);
            if (!(mid > worst.lo && mid < worst.hi)) {
                pieces.add(worst);
                break; // no finer interval exists in double
            }
            Piece left = rule(f, worst.lo, mid, dimension);
            Piece right = rule(f, mid, worst.hi, dimension);
            for (int k = 0; k < dimension; k++) {
                sum[k] += left.kronrod[k] + right.kronrod[k] - worst.kronrod[k];
            }
            errorSum += left.error + right.error - worst.error;
            pieces.add(left);
            pieces.add(right);
        }
        // re-add from the pieces: the running sum drifts by rounding
        for (Piece p : pieces) {
            for (int k = 0; k < dimension; k++) {
                total[k] += p.kronrod[k];
            }
        }
        return total;
    }

    /** One G7-K15 application over [lo, hi]: the Kronrod estimate and max_k |K15 - G7|. */
    private static Piece rule(DoubleFunction<double[]> f, double lo, double hi, int dimension) {
        double centre = 0.5 * (lo + hi);
        double half = 0.5 * (hi - lo);
        double[] kronrod = new double[dimension];
        double[] gauss = new double[dimension];
        for (int i = 0; i < NODES.length; i++) {
            double[] left = f.apply(centre - half * NODES[i]);
            double[] right = i == NODES.length - 1 ? null : f.apply(centre + half * NODES[i]);
            for (int k = 0; k < kronrod.length; k++) {
                double sum = right == null ? left[k] : left[k] + right[k];
                kronrod[k] += KRONROD_WEIGHTS[i] * sum;
                if (i % 2 == 1) {
                    gauss[k] += GAUSS_WEIGHTS[i / 2] * sum;
                }
            }
        }
        double error = 0;
        for (int k = 0; k < kronrod.length; k++) {
            kronrod[k] *= half;
            gauss[k] *= half;
            error = Math.max(error, Math.abs(kronrod[k] - gauss[k]));
        }
        return new Piece(lo, hi, kronrod, error);
    }
}
