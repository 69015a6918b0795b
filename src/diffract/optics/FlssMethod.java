package diffract.optics;

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
 * </table>
 */
final class FlssMethod implements Variant {
    @Override
    public String label() {
        return "flss";
    }

    @Override
    public boolean runsOnCpu() {
        return true;
    }

    @Override
    public boolean drawsLocalWindow() {
        return true;
    }

    @Override
    public DiffractionBrdf cpuBrdf(BrdfSettings settings, HeightField meanSubtracted, TaylorTerms terms) {
        return DiffractionBrdf.uniformlySampled(settings,
                DiffractionBrdf.gaussianWindowSpectrum(settings, terms, settings.taylor().highestOrder()));
    }

    @Override
    public DiffractionBrdf cpuBrdfPhaseCentred(BrdfSettings settings, PhaseCentredTerms terms) {
        int orders = terms.centres().highestOrder();
        return DiffractionBrdf.uniformlySampled(settings, new PhaseCentredSpectrum(terms,
                t -> DiffractionBrdf.gaussianWindowSpectrum(settings, t, orders)));
    }

    @Override
    public DiffractionBrdf cpuBrdfLocal(BrdfSettings settings, PatchSpectrum local) {
        return DiffractionBrdf.uniformlySampled(settings, local);
    }

    @Override
    public char viewerKey() {
        return '1';
    }

    @Override
    public String toString() {
        return name();
    }
}
