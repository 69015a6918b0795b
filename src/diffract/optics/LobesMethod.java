package diffract.optics;

import diffract.optics.illumination.DiscFootprint;
import diffract.optics.lobes.LobeWeightTable;
import diffract.optics.patches.HeightField;
import diffract.optics.settings.Quantity;
import diffract.optics.spectra.PhaseCentredTerms;
import diffract.optics.spectra.TaylorExpansion;
import diffract.optics.spectra.TaylorTerms;

import static diffract.optics.Variant.Capability.BAKEABLE;
import static diffract.optics.Variant.Capability.CPU;
import static diffract.optics.Variant.Capability.FILTERS_LIGHT;
import static diffract.optics.Variant.Capability.GPU;
import static diffract.optics.Variant.Capability.READS_CUTOFF;
import static diffract.optics.Variant.Capability.READS_TERMS;
import static diffract.optics.Variant.Capability.TAKES_RIGOROUS_ORDERS;

import java.util.EnumSet;
import java.util.Set;

/**
 * The windowed spectrum's Gaussian lobes, each widened by the pixel's footprint and the light and integrated over
 * wavelength by a rule fitted to its passage ({@link LobeSpectrum}, {@code lobes.frag}; docs/design/filtering.md): valid at
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
    public Set<Capability> capabilities() {
        return EnumSet.of(CPU, GPU, READS_TERMS, FILTERS_LIGHT, BAKEABLE, TAKES_RIGOROUS_ORDERS,
                READS_CUTOFF);
    }

    @Override
    public DiffractionBrdf cpuBrdf(BrdfSettings settings, HeightField meanSubtracted, TaylorTerms terms) {
        return DiffractionBrdf.withLobes(settings, LobeSpectrum.ofTerms(terms, settings.taylor().highestOrder(),
                settings.coherenceWindow(), settings.spectral(), settings.lobes())).withOrdersOf(meanSubtracted,
                settings);
    }

    @Override
    public DiffractionBrdf cpuBrdfPhaseCentred(BrdfSettings settings, PhaseCentredTerms terms) {
        return DiffractionBrdf.withLobes(settings, LobeSpectrum.ofTerms(terms, settings.coherenceWindow(),
                settings.spectral(), settings.lobes()));
    }

    @Override
    public java.util.Optional<String> patchRefusal(BrdfSettings settings, double widthUm, double heightUm) {
        return LobeQuadrature.wholeTexelsRefusal(settings, widthUm, heightUm);
    }

    /** The Taylor terms, and the weights per texel over the phase, and the texel sums where they apply. */
    @Override
    public diffract.util.MemoryEstimate heapMemory(HeightField field, BrdfSettings settings, double thetaIDeg,
                                                    double fromNm, double toNm) {
        diffract.util.MemoryEstimate estimate = Variant.super.heapMemory(field, settings, thetaIDeg, fromNm, toNm);
        estimate.plus("the lobes' weight table", LobeWeightTable.bytes(field.rows(), field.cols(),
                field.maxAbsHeightUm(), settings.spectral().lambdaMinNm(), settings.lobes().weightTolerance()));
        if (LobeSumTable.applies(settings.coherenceWindow(), settings.lobes(), field.widthUm(),
                field.heightExtentUm())) {
            estimate.plus("the lobes' texel sums", LobeSumTable.bytes(field.rows(), field.cols(),
                    LobeWeightTable.samples(field.maxAbsHeightUm(), settings.spectral().lambdaMinNm(),
                            settings.lobes().weightTolerance()),
                    settings.coherenceWindow().sigmaTexels(field.widthUm()),
                    settings.coherenceWindow().sigmaTexels(field.heightExtentUm())));
        }
        return estimate;
    }

    @Override
    public char viewerKey() {
        return '4';
    }

    /** It integrates wavelength exactly, sums whole texels and reads a float32 weight table. */
    @Override
    public java.util.Set<Quantity> unsweptSettings() {
        return java.util.Set.of(Quantity.LAMBDA_STEP, Quantity.WINDOW_RADIUS, Quantity.TERM_FORMAT,
                Quantity.TAYLOR_TOLERANCE);
    }

    /** As scenes draw it: phase-centred where float32 cannot reach the series' accuracy (the tall patch). */
    @Override
    public TaylorExpansion sweptExpansion() {
        return TaylorExpansion.AUTO;
    }

    @Override
    public String toString() {
        return name();
    }
}
