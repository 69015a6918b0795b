package diffract.optics;

import diffract.optics.patches.HeightField;
import diffract.optics.spectra.ExactSpectrum;
import diffract.optics.spectra.PhaseCentredTerms;
import diffract.optics.spectra.TaylorTerms;

import static diffract.optics.Variant.Capability.CPU;
import static diffract.optics.Variant.Capability.FILTERS_LIGHT;

import java.util.EnumSet;
import java.util.Set;

/**
 * The reference: exp(i k w h) transformed exactly, the window summed until its weights fall below 1e-12, the
 * wavelengths at 1 nm, a pixel's box and the light integrated where the illumination asks (the yardstick every other
 * method is measured against). CPU only.
 *
 * <table>
 *   <caption>Capabilities</caption>
 *   <tr><th>label</th><td>reference</td></tr>
 *   <tr><th>CPU / GPU</th><td>yes / no</td></tr>
 *   <tr><th>extended lights</th><td>integrated exactly (a disc per direction, {@link DiscLightAverage})</td></tr>
 * </table>
 */
final class ReferenceMethod implements Variant {
    @Override
    public String label() {
        return "reference";
    }

    @Override
    public Set<Capability> capabilities() {
        return EnumSet.of(CPU, FILTERS_LIGHT);
    }

    @Override
    public DiffractionBrdf cpuBrdf(BrdfSettings settings, HeightField meanSubtracted, TaylorTerms terms) {
        return DiffractionBrdf.reference(settings, meanSubtracted);
    }

    @Override
    public DiffractionBrdf cpuBrdfPhaseCentred(BrdfSettings settings, PhaseCentredTerms terms) {
        throw new IllegalArgumentException("the reference needs no Taylor expansion");
    }

    /** The exact spectrum of the patch over the band (or at the one wavelength), not Taylor terms. */
    @Override
    public diffract.util.MemoryEstimate heapMemory(HeightField field, BrdfSettings settings, double thetaIDeg,
                                                    double fromNm, double toNm) {
        return ExactSpectrum.memory(field, thetaIDeg, fromNm, toNm);
    }

    @Override
    public String toString() {
        return name();
    }
}
