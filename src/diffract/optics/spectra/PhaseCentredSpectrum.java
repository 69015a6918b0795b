package diffract.optics.spectra;

import java.util.function.Function;

/**
 * A Taylor-series spectrum (FLSS's and NMM's Gaussian window or PQ's sinc, unchanged) evaluated around the
 * nearest phase centre instead of around a = 0 ({@link PhaseCentres}): for a = k w it picks centre
 * a_j and sums sum_n (a - a_j)^n / n! E_{j,n}, the CPU mirror (in double over the float32 terms) of
 * {@code taylor_centred.glsl}. Each centre's spectrum sees the phase factor a - a_j, i.e. w - a_j / k: the window,
 * the lookup s = (u, v) L / lambda and PQ's replication factor do not depend on w and stay as they were.
 */
public final class PhaseCentredSpectrum implements PatchSpectrum {
    private final PhaseCentres centres;
    private final PatchSpectrum[] perCentre;

    /** @param spectrumOf builds the variant's spectrum over one centre's terms (all orders of that centre) */
    public PhaseCentredSpectrum(PhaseCentredTerms terms, Function<TaylorTerms, PatchSpectrum> spectrumOf) {
        this.centres = terms.centres();
        this.perCentre = new PatchSpectrum[centres.centreCount()];
        for (int j = 0; j < perCentre.length; j++) {
            perCentre[j] = spectrumOf.apply(terms.aroundCentre(j));
        }
    }

    @Override
    public double power(double u, double v, double w, double lambdaUm) {
        double k = 2.0 * Math.PI / lambdaUm;
        int j = centres.nearestCentre(k * w);
        // a - a_j = k (w - a_j / k): the centre's own series in the offset
        return perCentre[j].power(u, v, w - centres.centrePerUm(j) / k, lambdaUm);
    }

    @Override
    public double extentXUm() {
        return perCentre[0].extentXUm();
    }

    @Override
    public double extentYUm() {
        return perCentre[0].extentYUm();
    }

    public PhaseCentres centres() {
        return centres;
    }
}
