package diffract.optics;

import diffract.optics.patches.HeightField;
import diffract.optics.rigorous.RigorousSettings;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;
import diffract.optics.spectra.PhaseCentredTerms;
import diffract.optics.spectra.TaylorTerms;

import static diffract.optics.Variant.Capability.CPU;
import static diffract.optics.Variant.Capability.FILTERS_LIGHT;
import static diffract.optics.Variant.Capability.SOLVES_MAXWELL;

import java.util.EnumSet;
import java.util.Optional;
import java.util.Set;

/**
 * The rigorous method: the patch read as one period of a periodic surface, its reflected orders' efficiencies solved
 * from Maxwell's equations by the Fourier modal method ({@link diffract.optics.rigorous.FourierModalMethod}: both
 * polarisations, the material's complex index), and drawn into maps exactly as the reference draws its orders
 * (coherence window averaged over its position, pixel box, light, wavelength integral; {@link RigorousOrders}). The
 * yardstick beside the reference where Stam's scalar model is in doubt: deep reliefs and periods near the
 * wavelength (docs/design/rigorous.md). A 2-D patch is one crossed cell ({@link diffract.optics.rigorous.CellSolver}).
 * CPU only.
 *
 * <table>
 *   <caption>Capabilities</caption>
 *   <tr><th>label</th><td>rigorous</td></tr>
 *   <tr><th>CPU / GPU</th><td>yes / no</td></tr>
 *   <tr><th>extended lights</th><td>integrated as the reference does, the orders' efficiencies at the light's
 *       centre</td></tr>
 *   <tr><th>patches</th><td>1-D gratings (every row or column the same) of any period the harmonics resolve; 2-D
 *       cells whose eigenproblem keeps at most {@link RigorousPatch#MAX_UNKNOWNS} complex unknowns per layer
 *       (Laurent's rule; --harmonics 6 at most), larger ones refused before any work with the way out</td></tr>
 *   <tr><th>settings read</th><td>the band and its step (the wavelength nodes), the coherence length, the light, the
 *       pixel filter, the complex index, {@link RigorousSettings}</td></tr>
 * </table>
 */
final class RigorousMethod implements Variant {
    @Override
    public String label() {
        return "rigorous";
    }

    @Override
    public Set<Capability> capabilities() {
        return EnumSet.of(CPU, FILTERS_LIGHT, SOLVES_MAXWELL);
    }

    @Override
    public DiffractionBrdf cpuBrdf(BrdfSettings settings, HeightField meanSubtracted, TaylorTerms terms) {
        return DiffractionBrdf.rigorous(settings, meanSubtracted);
    }

    @Override
    public DiffractionBrdf cpuBrdfPhaseCentred(BrdfSettings settings, PhaseCentredTerms terms) {
        throw new IllegalArgumentException("the rigorous method needs no Taylor expansion");
    }

    @Override
    public Optional<String> patchRefusal(BrdfSettings settings, double widthUm, double heightUm) {
        return Optional.empty();
    }

    /**
     * The solver's matrices per worker thread (one solve per wavelength node, the nodes in parallel); a 2-D cell
     * beyond {@link RigorousPatch#MAX_UNKNOWNS} at the settings' harmonics is refused here, before any work.
     */
    @Override
    public diffract.util.MemoryEstimate heapMemory(HeightField field, BrdfSettings settings, double thetaIDeg,
                                                    double fromNm, double toNm) {
        RigorousPatch patch = RigorousPatch.of(field);
        patch.refusal(settings.rigorous().resolution(), fromNm * 1e-3).ifPresent(why -> {
            throw new InvalidSettingException(Quantity.VARIANT, why);
        });
        return RigorousCost.of(patch, settings, fromNm).memory();
    }

    /**
     * The refusal at the default resolution from 380 nm, for callers without settings (the viewer's A/B): 1-D
     * patches pass, and 2-D cells refused there (every one but the smallest, the default harmonics being many).
     */
    @Override
    public Optional<String> fieldRefusal(HeightField meanSubtracted) {
        return RigorousPatch.of(meanSubtracted).refusal();
    }

    @Override
    public String toString() {
        return name();
    }
}
