package diffract.optics;

import diffract.optics.spectra.PatchSpectrum;
import diffract.optics.spectra.TaylorTerms;

import static diffract.optics.Variant.Capability.BAKEABLE;
import static diffract.optics.Variant.Capability.CPU;
import static diffract.optics.Variant.Capability.GPU;
import static diffract.optics.Variant.Capability.LOCAL_WINDOW;
import static diffract.optics.Variant.Capability.READS_TERMS;

import java.util.EnumSet;
import java.util.Set;

/**
 * Full lambda-space sampling (003 Algorithm 3): uniform wavelength steps, N Taylor terms, the Gaussian window summed
 * over the texels around each lookup.
 *
 * <table>
 *   <caption>Capabilities</caption>
 *   <tr><th>label</th><td>flss</td></tr>
 *   <tr><th>CPU / GPU</th><td>yes / {@code flss.frag}</td></tr>
 *   <tr><th>extended lights</th><td>sampled at their centre</td></tr>
 *   <tr><th>local window</th><td>yes</td></tr>
 *   <tr><th>viewer key</th><td>1</td></tr>
 * </table>
 */
final class FlssMethod extends TaylorMethod {
    @Override
    public String label() {
        return "flss";
    }

    @Override
    public Set<Capability> capabilities() {
        return EnumSet.of(CPU, GPU, READS_TERMS, LOCAL_WINDOW, BAKEABLE);
    }

    @Override
    public char viewerKey() {
        return '1';
    }

    @Override
    PatchSpectrum spectrum(BrdfSettings settings, TaylorTerms terms, int highestOrder) {
        return DiffractionBrdf.gaussianWindowSpectrum(settings, terms, highestOrder);
    }

    @Override
    DiffractionBrdf sampled(BrdfSettings settings, PatchSpectrum spectrum) {
        return DiffractionBrdf.uniformlySampled(settings, spectrum);
    }
}
