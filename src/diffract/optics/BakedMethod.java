package diffract.optics;

import diffract.optics.patches.HeightField;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;
import diffract.optics.spectra.PhaseCentredTerms;
import diffract.optics.spectra.TaylorTerms;

import static diffract.optics.Variant.Capability.DRAWS_TABLE;
import static diffract.optics.Variant.Capability.FILTERS_LIGHT;
import static diffract.optics.Variant.Capability.GPU;
import static diffract.optics.Variant.Capability.READS_CUTOFF;
import static diffract.optics.Variant.Capability.READS_TERMS;

import java.util.EnumSet;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;

/**
 * A table XYZ(u, v, w) baked once per patch and settings and looked up trilinearly per fragment (after Dhillon and
 * Ghosh 2016, Toisoul and Ghosh 2017): a method that takes another method as its parameter, the one whose spectrum
 * the table holds ({@code baked(of=lobes)}, {@code baked(of=flss)}; any {@link Variant#bakeable} method). Plain
 * {@code baked} chooses per scene: the lobes method where the illumination filters (a pixel box or a light) and the
 * lobes shader takes the patch, else FLSS. GPU only: on the CPU the method it tabulates is the one to ask.
 *
 * <table>
 *   <caption>Capabilities</caption>
 *   <tr><th>label</th><td>baked</td></tr>
 *   <tr><th>parameter</th><td>{@code of}: the tabulated method (flss or lobes); none chooses as above</td></tr>
 *   <tr><th>CPU / GPU</th><td>no / {@code baked.frag}</td></tr>
 *   <tr><th>extended lights</th><td>the lobes method's table: a Gaussian baked in, isotropic; a disc integrated
 *   by the lookup over a table of the point light</td></tr>
 * </table>
 */
final class BakedMethod implements Variant {
    /** The tabulated method, or null: chosen per patch and settings. */
    private final Variant of;

    BakedMethod() {
        this.of = null;
    }

    private BakedMethod(Variant of) {
        this.of = of;
    }

    @Override
    public String label() {
        return "baked";
    }

    @Override
    public String spec() {
        return of == null ? label() : label() + "(of=" + of.spec() + ")";
    }

    @Override
    public Variant of(Variant inner) {
        if (!inner.bakeable()) {
            throw new InvalidSettingException(Quantity.VARIANT, "a baked table holds " + Methods.listed(
                    Variant::bakeable, "or") + ", not " + inner.spec());
        }
        return new BakedMethod(inner);
    }

    /** It filters the light where the method it holds does; chosen per scene, the lobes method does there. */
    @Override
    public Set<Capability> capabilities() {
        Set<Capability> capabilities = EnumSet.of(GPU, READS_TERMS, DRAWS_TABLE);
        if (of == null || of.filtersLight()) {
            capabilities.add(FILTERS_LIGHT);
        }
        if (of == null || of.readsCutoff()) {
            capabilities.add(READS_CUTOFF);
        }
        return capabilities;
    }

    @Override
    public Optional<Variant> tabulated(BrdfSettings settings, double widthUm, double heightUm) {
        if (of != null) {
            return Optional.of(of);
        }
        boolean lobes = settings.illumination().filters()
                && Variant.LOBES.patchRefusal(settings, widthUm, heightUm).isEmpty();
        return Optional.of(lobes ? Variant.LOBES : Variant.FLSS);
    }

    @Override
    public Optional<String> patchRefusal(BrdfSettings settings, double widthUm, double heightUm) {
        return of == null ? Optional.empty() : of.patchRefusal(settings, widthUm, heightUm);
    }

    /**
     * What its bake keeps (the tabulated method's heap; plain {@code baked}: the lobes method's, the larger), the
     * table's float32 host copy and, for a filtered table under a disc, its rows' running sums.
     */
    @Override
    public diffract.util.MemoryEstimate heapMemory(HeightField field, BrdfSettings settings, double thetaIDeg,
                                                    double fromNm, double toNm) {
        Variant baking = of != null ? of : Variant.LOBES;
        BakedGrid grid = BakedGrid.of(settings, field.maxAbsHeightUm());
        diffract.util.MemoryEstimate estimate = baking.heapMemory(field, settings, thetaIDeg, fromNm, toNm).plus(
                String.format(java.util.Locale.ROOT, "baked table %d x %d x %d", grid.uvSamples(), grid.uvSamples(),
                        grid.wSamples()), grid.bytes(12));
        // under a disc the lookup of a filtered table reads the running sums of its rows, a second float32 copy
        return baking.filtersLight() && settings.illumination().light().isDisc()
                ? estimate.plus("its rows' running sums", grid.bytes(12)) : estimate;
    }

    @Override
    public DiffractionBrdf cpuBrdf(BrdfSettings settings, HeightField meanSubtracted, TaylorTerms terms) {
        throw new InvalidSettingException(Quantity.VARIANT, DiffractionBrdf.BAKED_IS_GPU_ONLY);
    }

    @Override
    public DiffractionBrdf cpuBrdfPhaseCentred(BrdfSettings settings, PhaseCentredTerms terms) {
        throw new InvalidSettingException(Quantity.VARIANT, DiffractionBrdf.BAKED_IS_GPU_ONLY);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof BakedMethod b && Objects.equals(b.of, of);
    }

    @Override
    public int hashCode() {
        return Objects.hashCode(of) * 31 + 7;
    }

    /** It tabulates its method at the thesis' point once per patch; its own grid is automatic. */
    @Override
    public java.util.Set<Quantity> unsweptSettings() {
        return java.util.Set.of(Quantity.HIGHEST_ORDER, Quantity.LAMBDA_STEP, Quantity.WINDOW_RADIUS,
                Quantity.TERM_FORMAT, Quantity.TAYLOR_TOLERANCE);
    }

    @Override
    public String toString() {
        return of == null ? name() : name() + "(OF=" + of + ")";
    }
}
