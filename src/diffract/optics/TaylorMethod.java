package diffract.optics;

import diffract.optics.patches.HeightField;
import diffract.optics.spectra.PatchSpectrum;
import diffract.optics.spectra.PhaseCentredSpectrum;
import diffract.optics.spectra.PhaseCentredTerms;
import diffract.optics.spectra.TaylorTerms;

import static diffract.optics.Variant.Capability.CPU;
import static diffract.optics.Variant.Capability.GPU;
import static diffract.optics.Variant.Capability.READS_TERMS;

import java.util.EnumSet;
import java.util.Set;

/**
 * The thesis' three shader approximations on the CPU (FLSS, NMM, PQ): the Taylor series over the float32 terms
 * (003 eq. 1.5-1.10), under the method's window ({@link #spectrum}), at the method's wavelengths ({@link #sampled});
 * around 0 or around the nearest phase centre ({@link PhaseCentredSpectrum}).
 */
abstract class TaylorMethod implements Variant {
    /** The series of orders 0..highestOrder over {@code terms} under the method's window. */
    abstract PatchSpectrum spectrum(BrdfSettings settings, TaylorTerms terms, int highestOrder);

    /** {@code spectrum} integrated over the method's wavelengths. */
    abstract DiffractionBrdf sampled(BrdfSettings settings, PatchSpectrum spectrum);

    /** A CPU twin of a GPU shader that reads the Taylor terms. */
    @Override
    public Set<Capability> capabilities() {
        return EnumSet.of(CPU, GPU, READS_TERMS);
    }

    @Override
    public DiffractionBrdf cpuBrdf(BrdfSettings settings, HeightField meanSubtracted, TaylorTerms terms) {
        return sampled(settings, spectrum(settings, terms, settings.taylor().highestOrder()));
    }

    @Override
    public DiffractionBrdf cpuBrdfPhaseCentred(BrdfSettings settings, PhaseCentredTerms terms) {
        int orders = terms.centres().highestOrder();
        return sampled(settings, new PhaseCentredSpectrum(terms, t -> spectrum(settings, t, orders)));
    }

    @Override
    public DiffractionBrdf cpuBrdfLocal(BrdfSettings settings, PatchSpectrum local) {
        if (!drawsLocalWindow()) {
            return Variant.super.cpuBrdfLocal(settings, local);
        }
        return sampled(settings, local);
    }

    @Override
    public String toString() {
        return name();
    }
}
