package diffract.optics.spectra;

import java.util.List;

/**
 * The float32 terms of the phase-centred expansion ({@link PhaseCentres}): for every centre a_j the
 * terms E_{j,n} = fftshift(ifft2(exp(i a_j h) (i h)^n)), n = 0..centres.highestOrder(), each stored exactly like
 * the thesis' {@link TaylorTerms} (which are the centre a_0 = 0). Immutable.
 */
public final class PhaseCentredTerms {
    private final PhaseCentres centres;
    private final TaylorTerms[] perCentre;

    /** @param perCentre the terms around centre j at index j; not copied: the caller hands them over */
    public PhaseCentredTerms(PhaseCentres centres, TaylorTerms[] perCentre) {
        if (perCentre.length != centres.centreCount()) {
            throw new IllegalArgumentException(perCentre.length + " term sets for " + centres.centreCount() + " centres");
        }
        for (TaylorTerms t : perCentre) {
            if (t.highestOrder() != centres.highestOrder() || t.rows() != perCentre[0].rows()
                    || t.cols() != perCentre[0].cols()) {
                throw new IllegalArgumentException("every centre needs terms 0.." + centres.highestOrder()
                        + " of one patch size");
            }
        }
        this.centres = centres;
        this.perCentre = perCentre;
    }

    public PhaseCentres centres() {
        return centres;
    }

    /** The terms around centre j. */
    public TaylorTerms aroundCentre(int j) {
        return perCentre[j];
    }

    public int rows() {
        return perCentre[0].rows();
    }

    public int cols() {
        return perCentre[0].cols();
    }

    /** Texture-array layers in the shader's order: layer j * (N_c + 1) + n holds E_{j,n}. */
    public List<float[]> layers() {
        List<float[]> out = new java.util.ArrayList<>(centres.layerCount());
        for (TaylorTerms t : perCentre) {
            for (int n = 0; n <= t.highestOrder(); n++) {
                out.add(t.termData(n));
            }
        }
        return out;
    }
}
