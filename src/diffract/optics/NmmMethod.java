package diffract.optics;

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
 * </table>
 */
final class NmmMethod implements Variant {
    @Override
    public String label() {
        return "nmm";
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
        return DiffractionBrdf.sampledOnTexelCentres(settings,
                DiffractionBrdf.gaussianWindowSpectrum(settings, terms, settings.taylor().highestOrder()));
    }

    @Override
    public DiffractionBrdf cpuBrdfPhaseCentred(BrdfSettings settings, PhaseCentredTerms terms) {
        int orders = terms.centres().highestOrder();
        return DiffractionBrdf.sampledOnTexelCentres(settings, new PhaseCentredSpectrum(terms,
                t -> DiffractionBrdf.gaussianWindowSpectrum(settings, t, orders)));
    }

    @Override
    public DiffractionBrdf cpuBrdfLocal(BrdfSettings settings, PatchSpectrum local) {
        return DiffractionBrdf.sampledOnTexelCentres(settings, local);
    }

    @Override
    public char viewerKey() {
        return '2';
    }

    @Override
    public String toString() {
        return name();
    }
}
