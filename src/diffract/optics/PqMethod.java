package diffract.optics;

/**
 * Periodic replication and sinc interpolation (003 section 1.5.3, 004 "PQ factors"): the patch repeated so that the
 * window covers whole replicas, the DFT interpolated between texels by the sinc of the replicated extent.
 *
 * <table>
 *   <caption>Capabilities</caption>
 *   <tr><th>label</th><td>pq</td></tr>
 *   <tr><th>CPU / GPU</th><td>yes / {@code pq.frag}</td></tr>
 *   <tr><th>extended lights</th><td>sampled at their centre</td></tr>
 * </table>
 */
final class PqMethod implements Variant {
    @Override
    public String label() {
        return "pq";
    }

    @Override
    public boolean runsOnCpu() {
        return true;
    }

    @Override
    public DiffractionBrdf cpuBrdf(BrdfSettings settings, HeightField meanSubtracted, TaylorTerms terms) {
        return DiffractionBrdf.uniformlySampled(settings,
                DiffractionBrdf.sincSpectrum(settings, terms, settings.taylor().highestOrder()));
    }

    @Override
    public DiffractionBrdf cpuBrdfPhaseCentred(BrdfSettings settings, PhaseCentredTerms terms) {
        int orders = terms.centres().highestOrder();
        return DiffractionBrdf.uniformlySampled(settings, new PhaseCentredSpectrum(terms,
                t -> DiffractionBrdf.sincSpectrum(settings, t, orders)));
    }

    @Override
    public char viewerKey() {
        return '3';
    }

    @Override
    public String toString() {
        return name();
    }
}
