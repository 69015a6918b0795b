package diffract.optics.rigorous;

import java.util.ArrayList;
import java.util.List;

/**
 * A 2-D cell's relief cut into slabs of equal thickness, as {@link Staircase} cuts a 1-D profile: slab j of L, counted
 * from the top, holds the material at every sample whose height exceeds the middle of the slab's height range,
 * min + depth (1 - (j + 1/2) / L). A cell of a few distinct heights (pillars, terraces) gives few distinct slabs, which
 * {@link CellFourierModalMethod} solves once each.
 */
public final class CellStaircase {
    private CellStaircase() {
    }

    /** The {@code layers} slabs of the cell, top first; none for a flat cell. */
    public static List<CellSlab> of(CellRelief relief, int layers) {
        if (layers < 1) {
            throw new IllegalArgumentException("a staircase needs at least one layer, got " + layers);
        }
        List<CellSlab> slabs = new ArrayList<>(layers);
        double depth = relief.depthUm();
        if (depth == 0) {
            return slabs;
        }
        double lo = relief.minHeightUm();
        double[] h = relief.heightsUm();
        for (int j = 0; j < layers; j++) {
            double level = lo + depth * (1 - (j + 0.5) / layers);
            boolean[] mask = new boolean[h.length];
            for (int i = 0; i < h.length; i++) {
                mask[i] = h[i] > level;
            }
            slabs.add(new CellSlab(depth / layers, relief.cols(), relief.rows(), mask));
        }
        return slabs;
    }
}
