package diffract.optics.rigorous;

import java.util.List;

/**
 * A 1-D grating as the Fourier modal method sees it: air above, the relief as a stack of {@link Slab}s (top first)
 * of one material, and a half-space of the substrate below (for a scale: the same keratin).
 *
 * @param periodUm  the period across the grooves, um
 * @param slabs     the relief's layers, top first; empty: a flat interface
 * @param material  the relief's index
 * @param substrate the index below the relief
 */
public record Grating(double periodUm, List<Slab> slabs, ComplexIndex material, ComplexIndex substrate) {
    public Grating {
        if (!(periodUm > 0) || !Double.isFinite(periodUm)) {
            throw new IllegalArgumentException("a grating's period must be > 0 um, got " + periodUm);
        }
        slabs = List.copyOf(slabs);
    }

    /** The relief's staircase of {@code layers} slabs over the bulk of the same material. */
    public static Grating of(Profile profile, int layers, ComplexIndex material) {
        return new Grating(profile.periodUm(), Staircase.of(profile, layers), material, material);
    }

    /** A flat interface to {@code substrate}, seen with the given period (orders other than 0 carry nothing). */
    public static Grating flat(double periodUm, ComplexIndex substrate) {
        return new Grating(periodUm, List.of(), substrate, substrate);
    }
}
