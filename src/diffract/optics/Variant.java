package diffract.optics;

import diffract.optics.patches.HeightField;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.OrderWeights;
import diffract.optics.settings.Quantity;
import diffract.optics.spectra.PatchSpectrum;
import diffract.optics.spectra.PhaseCentredSpectrum;
import diffract.optics.spectra.PhaseCentredTerms;
import diffract.optics.spectra.TaylorExpansion;
import diffract.optics.spectra.TaylorTerms;

import java.util.List;
import java.util.Locale;

/**
 * A way of evaluating the diffraction BRDF: one class per method, found by its {@link #label()} in {@link Methods}.
 * The methods: {@link ReferenceMethod} (the exact reference), {@link FlssMethod}, {@link NmmMethod} and
 * {@link PqMethod} (the thesis' three shader approximations), {@link BakedMethod} (a baked table, GPU only) and
 * {@link LobesMethod} (the filtered lobes method), and {@link RigorousMethod} (the orders from Maxwell's equations).
 *
 * <p>What a method says about itself (every method answers; the defaults are those of a GPU shader that samples the
 * light at its centre and has no CPU twin):
 *
 * <table>
 *   <caption>A method's capabilities</caption>
 *   <tr><th>method</th><th>what it answers</th><th>default</th></tr>
 *   <tr><td>{@link #label}</td><td>the name on the command line, in scene files and in tables</td><td>-</td></tr>
 *   <tr><td>{@link #capabilities}</td><td>its {@link Capability} set: on the CPU, on the GPU, filters the light,
 *       reads the Taylor terms, sums a local window, can be baked, draws a table, takes the rigorous orders, reads the
 *       exposure's cutoff, solves Maxwell's equations</td><td>on the GPU, reads the
 *       terms</td></tr>
 *   <tr><td>{@link #viewerKey}</td><td>the viewer's key that selects it</td><td>none</td></tr>
 *   <tr><td>{@link #tabulated}</td><td>the method a table of it holds</td><td>no table</td></tr>
 *   <tr><td>{@link #of}, {@link #spec}</td><td>the method with another as its parameter, and its name then</td>
 *       <td>takes none; the label</td></tr>
 *   <tr><td>{@link #patchRefusal}</td><td>why its shader cannot draw a patch</td><td>draws every patch</td></tr>
 *   <tr><td>{@link #heapMemory}</td><td>the heap its evaluation takes</td><td>the Taylor terms</td></tr>
 *   <tr><td>{@link #unsweptSettings}, {@link #sweptExpansion}</td><td>what the bench's sweep holds fixed for it, and
 *       the expansion it sums there</td><td>none; the thesis' series</td></tr>
 * </table>
 *
 * <p>Which method plays which role when a command names none is {@link Methods.Role}'s table.
 *
 * <p>A new method is a class implementing this interface, registered with {@link Methods#register}; the commands,
 * scene files and the bench then find it by its label.
 */
public interface Variant {
    Variant REFERENCE = new ReferenceMethod();
    Variant FLSS = new FlssMethod();
    Variant NMM = new NmmMethod();
    Variant PQ = new PqMethod();
    Variant BAKED = new BakedMethod();
    Variant LOBES = new LobesMethod();
    Variant RIGOROUS = new RigorousMethod();

    /** reference, flss, nmm, pq, baked, lobes: the name on the command line, in scene files and in tables. */
    String label();

    /**
     * What a method can do, as pbrt's BxDF flags say it of a BxDF: each method answers with its set once
     * ({@link #capabilities}), and the questions below read it.
     */
    enum Capability {
        /** {@link #cpuBrdf} evaluates it (the baked table exists on the GPU only). */
        CPU,
        /** It runs as a GPU shader, {@code shaders/diffraction/<label>.frag} (all but the reference). */
        GPU,
        /**
         * It averages over an extended light's directions (the reference, the lobes method and its baked table); the
         * others sample the light at its centre.
         */
        FILTERS_LIGHT,
        /**
         * It reads the precomputed Taylor terms (every method but the reference, which transforms the height field
         * itself): a pipeline computes them for it.
         */
        READS_TERMS,
        /** It sums the window's texels per fragment and so can place the window under each surface point. */
        LOCAL_WINDOW,
        /** A baked table can tabulate it: its shader has a bake pass that writes spectral XYZ per table sample. */
        BAKEABLE,
        /** It draws a table baked in advance ({@link #tabulated} answers for every patch). */
        DRAWS_TABLE,
        /**
         * Its lobes can take the orders' efficiencies from Maxwell's equations in place of the scalar model's
         * ({@link OrderWeights#RIGOROUS}, {@link OrderCorrection}).
         */
        TAKES_RIGOROUS_ORDERS,
        /**
         * Its picture depends on the exposure it is shown at: it drops the lobes fainter than a cutoff of the shown
         * white ({@link LobeQuadrature#shownAt}), so a map whose exposure comes from the map itself is drawn again.
         */
        READS_CUTOFF,
        /** Its orders come from Maxwell's equations: the scalar model's validity does not concern it. */
        SOLVES_MAXWELL
    }

    /** What it can do; by default, a GPU shader that reads the Taylor terms. */
    default java.util.Set<Capability> capabilities() {
        return java.util.EnumSet.of(Capability.GPU, Capability.READS_TERMS);
    }

    /** {@link Capability#CPU}. */
    default boolean runsOnCpu() {
        return capabilities().contains(Capability.CPU);
    }

    /** {@link Capability#GPU}. */
    default boolean runsOnGpu() {
        return capabilities().contains(Capability.GPU);
    }

    /** {@link Capability#FILTERS_LIGHT}. */
    default boolean filtersLight() {
        return capabilities().contains(Capability.FILTERS_LIGHT);
    }

    /** {@link Capability#READS_TERMS}. */
    default boolean readsTerms() {
        return capabilities().contains(Capability.READS_TERMS);
    }

    /** {@link Capability#LOCAL_WINDOW}. */
    default boolean drawsLocalWindow() {
        return capabilities().contains(Capability.LOCAL_WINDOW);
    }

    /** The viewer's key that switches to it ('1' to '4' for FLSS, NMM, PQ and lobes), 0 for none. */
    default char viewerKey() {
        return 0;
    }

    /** {@link Capability#BAKEABLE}. */
    default boolean bakeable() {
        return capabilities().contains(Capability.BAKEABLE);
    }

    /**
     * The method a table of this one holds for {@code settings} on a patch of {@code widthUm} x {@code heightUm}, or
     * empty when it draws without a table (every method but {@link BakedMethod}).
     */
    default java.util.Optional<Variant> tabulated(BrdfSettings settings, double widthUm, double heightUm) {
        return java.util.Optional.empty();
    }

    /**
     * Why its shader cannot draw a patch of {@code widthUm} x {@code heightUm} with {@code settings}, or empty when it
     * can (the lobes shader sums whole texels and refuses a window that keeps texel pairs; a scene then draws the
     * fallback method, {@link Methods.Role#FALLBACK}).
     */
    default java.util.Optional<String> patchRefusal(BrdfSettings settings, double widthUm, double heightUm) {
        return java.util.Optional.empty();
    }

    /**
     * Why it cannot draw the height field {@code meanSubtracted} at all, or empty when it can (every method but the
     * rigorous one, which solves 1-D patches and small 2-D cells): for callers that offer a method only where it
     * applies.
     */
    default java.util.Optional<String> fieldRefusal(HeightField meanSubtracted) {
        return java.util.Optional.empty();
    }

    /** {@link Capability#DRAWS_TABLE}. */
    default boolean drawsTable() {
        return capabilities().contains(Capability.DRAWS_TABLE);
    }

    /** {@link Capability#READS_CUTOFF}. */
    default boolean readsCutoff() {
        return capabilities().contains(Capability.READS_CUTOFF);
    }

    /** {@link Capability#SOLVES_MAXWELL}. */
    default boolean solvesMaxwell() {
        return capabilities().contains(Capability.SOLVES_MAXWELL);
    }

    /** {@link Capability#TAKES_RIGOROUS_ORDERS}. */
    default boolean takesRigorousOrders() {
        return capabilities().contains(Capability.TAKES_RIGOROUS_ORDERS);
    }

    /**
     * This method taking {@code inner} as its parameter ({@code baked(of=lobes)}), or a refusal when it takes none or
     * not that one.
     */
    default Variant of(Variant inner) {
        throw new InvalidSettingException(Quantity.VARIANT, label() + " takes no other method; " + label() + "(of="
                + inner.label() + ") is not a method");
    }

    /** How the command line and scene files name it: its label, with its parameter where it has one. */
    default String spec() {
        return label();
    }

    /**
     * The BRDF on the CPU for {@code settings} (whose variant is this one): {@code terms} are the precomputed
     * float32 Taylor terms, {@code meanSubtracted} the height field (the reference's). The light policy and the
     * window's placement are checked by {@link DiffractionBrdf#create} before it is asked.
     */
    default DiffractionBrdf cpuBrdf(BrdfSettings settings, HeightField meanSubtracted, TaylorTerms terms) {
        throw new InvalidSettingException(Quantity.VARIANT, label() + " has no CPU evaluation");
    }

    /** As {@link #cpuBrdf} summed around the nearest phase centre ({@link PhaseCentredSpectrum}). */
    default DiffractionBrdf cpuBrdfPhaseCentred(BrdfSettings settings, PhaseCentredTerms terms) {
        throw new InvalidSettingException(Quantity.VARIANT, label() + " has no phase-centred expansion");
    }

    /**
     * As {@link #cpuBrdf} with the window under one surface point ({@link DiffractionBrdf#createLocal}): {@code local}
     * is the Gaussian window's spectrum there, which a method that {@link #drawsLocalWindow} samples in wavelength.
     */
    default DiffractionBrdf cpuBrdfLocal(BrdfSettings settings, PatchSpectrum local) {
        throw new InvalidSettingException(Quantity.WINDOW_PLACEMENT, DiffractionBrdf.LOCAL_NEEDS_FLSS_OR_NMM);
    }

    /**
     * The heap its evaluation of {@code field} takes beyond the picture's own buffers, part by part: the Taylor terms
     * unless it keeps more (its tables) or other things (the reference's exact spectrum between {@code fromNm} and
     * {@code toNm} at theta_i {@code thetaIDeg}).
     */
    default diffract.util.MemoryEstimate heapMemory(HeightField field, BrdfSettings settings, double thetaIDeg,
                                                     double fromNm, double toNm) {
        int termCount = settings.taylor().highestOrder() + 1;
        return diffract.util.MemoryEstimate.of(termCount + " Taylor terms", 8L * field.rows() * field.cols()
                * termCount);
    }

    /**
     * The settings a sweep of the bench holds at the thesis' value for it: those it does not read, or fixes itself
     * (none: it reads every setting the bench sweeps).
     */
    default java.util.Set<Quantity> unsweptSettings() {
        return java.util.Set.of();
    }

    /**
     * The Taylor expansion a sweep of the bench sums for it: the thesis' series around 0 (what the bench measures of
     * the thesis' methods, the series' truncation included), unless it draws scenes with the expansion the pipeline
     * chooses.
     */
    default TaylorExpansion sweptExpansion() {
        return TaylorExpansion.PLAIN;
    }

    /** The label in capitals, as the methods' constants are named (FLSS, LOBES). */
    default String name() {
        return label().toUpperCase(Locale.ROOT);
    }

    /** Every registered method, the built-in ones first ({@link Methods#all}). */
    static Variant[] values() {
        List<Variant> all = Methods.all();
        return all.toArray(new Variant[0]);
    }

    /**
     * The method of a {@link #label()} (any case), or of a label with its parameter ({@code baked(of=lobes)}), or a
     * refusal that lists the registered ones.
     */
    static Variant parse(String text) {
        return Methods.named(text);
    }
}
