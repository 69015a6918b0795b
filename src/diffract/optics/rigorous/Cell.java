package diffract.optics.rigorous;

import java.util.List;

/**
 * A 2-D cell as the Fourier modal method sees it, as {@link Grating} is a 1-D one: air above, the relief as a stack
 * of {@link CellSlab}s (top first) of one material, and a half-space of the substrate below.
 *
 * @param periodXUm the period along x, um
 * @param periodYUm the period along y, um
 * @param slabs     the relief's layers, top first; empty: a flat interface
 * @param material  the relief's index
 * @param substrate the index below the relief
 */
public record Cell(double periodXUm, double periodYUm, List<CellSlab> slabs, ComplexIndex material,
                   ComplexIndex substrate) {
    public Cell {
        if (!(periodXUm > 0) || !(periodYUm > 0) || !Double.isFinite(periodXUm) || !Double.isFinite(periodYUm)) {
            throw new IllegalArgumentException("a cell's periods must be > 0 um, got " + periodXUm + " x " + periodYUm);
        }
        slabs = List.copyOf(slabs);
    }

    /** The relief's staircase of {@code layers} slabs over the bulk of the same material. */
    public static Cell of(CellRelief relief, int layers, ComplexIndex material) {
        return new Cell(relief.periodXUm(), relief.periodYUm(), CellStaircase.of(relief, layers), material, material);
    }

    /** A flat interface to {@code substrate}, seen with the given periods (orders other than (0, 0) carry nothing). */
    public static Cell flat(double periodXUm, double periodYUm, ComplexIndex substrate) {
        return new Cell(periodXUm, periodYUm, List.of(), substrate, substrate);
    }
}
