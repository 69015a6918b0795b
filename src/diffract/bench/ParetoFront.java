package diffract.bench;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.function.ToDoubleFunction;

/**
 * The Pareto front of (cost, error) points: those no other point beats in both, i.e. no other point is at most
 * as costly and at most as wrong and better in one of the two. Points with a NaN coordinate are never on it.
 */
public final class ParetoFront {
    private ParetoFront() {
    }

    /** The front, sorted by increasing cost (and so by decreasing error); of exact duplicates, the first. */
    public static <T> List<T> of(List<T> points, ToDoubleFunction<T> cost, ToDoubleFunction<T> error) {
        List<T> sorted = new ArrayList<>();
        for (T p : points) {
            if (!Double.isNaN(cost.applyAsDouble(p)) && !Double.isNaN(error.applyAsDouble(p))) {
                sorted.add(p);
            }
        }
        // stable sort: by cost, then by error, so the first of equal-cost points is the most accurate
        sorted.sort(Comparator.comparingDouble(cost).thenComparingDouble(error));
        List<T> front = new ArrayList<>();
        double bestError = Double.POSITIVE_INFINITY;
        for (T p : sorted) {
            double e = error.applyAsDouble(p);
            if (e < bestError) {
                front.add(p);
                bestError = e;
            }
        }
        return front;
    }
}
