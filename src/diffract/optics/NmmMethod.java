package diffract.optics;

import diffract.optics.settings.Quantity;
import diffract.optics.spectra.PatchSpectrum;
import diffract.optics.spectra.TaylorTerms;

import static diffract.optics.Variant.Capability.CPU;
import static diffract.optics.Variant.Capability.GPU;
import static diffract.optics.Variant.Capability.LOCAL_WINDOW;
import static diffract.optics.Variant.Capability.READS_TERMS;

import java.util.EnumSet;
import java.util.Set;

/**
 * n_min / n_max (003 section 1.5.2): FLSS's spectrum at only the wavelengths that put a lookup on a DFT texel's
 * centre, with the Jacobian of that change of variable.
 *
 * <table>
 *   <caption>Capabilities</caption>
 *   <tr><th>label</th><td>nmm</td></tr>
 *   <tr><th>CPU / GPU</th><td>yes / {@code nmm.frag}</td></tr>
 *   <tr><th>extended lights</th><td>sampled at their centre</td></tr>
 *   <tr><th>local window</th><td>yes</td></tr>
 *   <tr><th>viewer key</th><td>2</td></tr>
 * </table>
 */
final class NmmMethod extends TaylorMethod {
    @Override
    public String label() {
        return "nmm";
    }

    @Override
    public Set<Capability> capabilities() {
        return EnumSet.of(CPU, GPU, READS_TERMS, LOCAL_WINDOW);
    }

    @Override
    public char viewerKey() {
        return '2';
    }

    @Override
    PatchSpectrum spectrum(BrdfSettings settings, TaylorTerms terms, int highestOrder) {
        return DiffractionBrdf.gaussianWindowSpectrum(settings, terms, highestOrder);
    }

    @Override
    DiffractionBrdf sampled(BrdfSettings settings, PatchSpectrum spectrum) {
        return DiffractionBrdf.sampledOnTexelCentres(settings, spectrum);
    }

    /**
     * Its wavelengths come from the patch (lambda = u L / m, 003 sec. 1.5.2); its lambda step only serves the
     * fallback near the specular direction and stays at the thesis' 5 nm.
     */
    @Override
    public java.util.Set<Quantity> unsweptSettings() {
        return java.util.Set.of(Quantity.LAMBDA_STEP);
    }
}
