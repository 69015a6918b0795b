package diffract.optics;

import diffract.optics.spectra.PatchSpectrum;
import diffract.optics.spectra.TaylorTerms;

/**
 * Periodic replication and sinc interpolation (003 section 1.5.3, 004 "PQ factors"): the patch repeated so that the
 * window covers whole replicas, the DFT interpolated between texels by the sinc of the replicated extent.
 *
 * <table>
 *   <caption>Capabilities</caption>
 *   <tr><th>label</th><td>pq</td></tr>
 *   <tr><th>CPU / GPU</th><td>yes / {@code pq.frag}</td></tr>
 *   <tr><th>extended lights</th><td>sampled at their centre</td></tr>
 *   <tr><th>viewer key</th><td>3</td></tr>
 * </table>
 */
final class PqMethod extends TaylorMethod {
    @Override
    public String label() {
        return "pq";
    }

    @Override
    public char viewerKey() {
        return '3';
    }

    @Override
    PatchSpectrum spectrum(BrdfSettings settings, TaylorTerms terms, int highestOrder) {
        return DiffractionBrdf.sincSpectrum(settings, terms, highestOrder);
    }

    @Override
    DiffractionBrdf sampled(BrdfSettings settings, PatchSpectrum spectrum) {
        return DiffractionBrdf.uniformlySampled(settings, spectrum);
    }
}
