package diffract.optics;

/**
 * The windowed spectrum's Gaussian lobes, each widened by the pixel's footprint and the light and integrated over
 * wavelength by a rule fitted to its passage ({@link LobeSpectrum}, {@code lobes.frag}; docs/filtering.md): valid at
 * the true coherence length.
 *
 * <table>
 *   <caption>Capabilities</caption>
 *   <tr><th>label</th><td>lobes</td></tr>
 *   <tr><th>CPU / GPU</th><td>yes / {@code lobes.frag}</td></tr>
 *   <tr><th>extended lights</th><td>averaged over (a Gaussian, or a disc per lobe, {@link DiscFootprint})</td></tr>
 *   <tr><th>viewer key</th><td>4</td></tr>
 * </table>
 */
final class LobesMethod implements Variant {
    @Override
    public String label() {
        return "lobes";
    }

    @Override
    public boolean runsOnCpu() {
        return true;
    }

    @Override
    public boolean filtersLight() {
        return true;
    }

    @Override
    public DiffractionBrdf cpuBrdf(BrdfSettings settings, HeightField meanSubtracted, TaylorTerms terms) {
        return DiffractionBrdf.withLobes(settings, LobeSpectrum.ofTerms(terms, settings.taylor().highestOrder(),
                settings.coherenceWindow(), settings.spectral(), settings.lobes()));
    }

    @Override
    public DiffractionBrdf cpuBrdfPhaseCentred(BrdfSettings settings, PhaseCentredTerms terms) {
        return DiffractionBrdf.withLobes(settings, LobeSpectrum.ofTerms(terms, settings.coherenceWindow(),
                settings.spectral(), settings.lobes()));
    }

    @Override
    public char viewerKey() {
        return '4';
    }

    @Override
    public String toString() {
        return name();
    }
}
