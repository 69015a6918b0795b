package diffract.optics;

import java.util.List;
import java.util.Locale;

/**
 * A way of evaluating the diffraction BRDF: one class per method, found by its {@link #label()} in {@link Methods}.
 * The methods: {@link ReferenceMethod} (the exact reference), {@link FlssMethod}, {@link NmmMethod} and
 * {@link PqMethod} (the thesis' three shader approximations), {@link BakedMethod} (a baked table, GPU only) and
 * {@link LobesMethod} (the filtered lobes method).
 *
 * <p>What a method says about itself (every method answers; the defaults are those of a GPU shader that samples the
 * light at its centre and has no CPU twin):
 *
 * <table>
 *   <caption>A method's capabilities</caption>
 *   <tr><th>method</th><th>what it answers</th><th>default</th></tr>
 *   <tr><td>{@link #label}</td><td>the name on the command line, in scene files and in tables</td><td>-</td></tr>
 *   <tr><td>{@link #runsOnCpu}</td><td>whether {@link #cpuBrdf} evaluates it</td><td>false</td></tr>
 *   <tr><td>{@link #runsOnGpu}</td><td>whether a fragment shader {@code shaders/diffraction/<label>.frag} draws it
 *       </td><td>true</td></tr>
 *   <tr><td>{@link #filtersLight}</td><td>whether it averages over an extended light's directions</td>
 *       <td>false</td></tr>
 *   <tr><td>{@link #drawsLocalWindow}</td><td>whether it sums a local window's texels per fragment</td>
 *       <td>false</td></tr>
 *   <tr><td>{@link #viewerKey}</td><td>the viewer's key that selects it</td><td>none</td></tr>
 * </table>
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

    /** reference, flss, nmm, pq, baked, lobes: the name on the command line, in scene files and in tables. */
    String label();

    /** Whether {@link #cpuBrdf} evaluates it (the baked table exists on the GPU only). */
    default boolean runsOnCpu() {
        return false;
    }

    /** Whether it runs as a GPU shader, {@code shaders/diffraction/<label>.frag} (all but the reference). */
    default boolean runsOnGpu() {
        return true;
    }

    /**
     * Whether it averages over an extended light's directions (the lobes method and its baked table); the reference
     * does too but draws no scenes, and the others sample the light at its centre.
     */
    default boolean filtersLight() {
        return false;
    }

    /** Whether it sums the window's texels per fragment and so can place the window under each surface point. */
    default boolean drawsLocalWindow() {
        return false;
    }

    /** The viewer's key that switches to it ('1' to '4' for FLSS, NMM, PQ and lobes), 0 for none. */
    default char viewerKey() {
        return 0;
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

    /** The label in capitals, as the methods' constants are named (FLSS, LOBES). */
    default String name() {
        return label().toUpperCase(Locale.ROOT);
    }

    /** Every registered method, the built-in ones first ({@link Methods#all}). */
    static Variant[] values() {
        List<Variant> all = Methods.all();
        return all.toArray(new Variant[0]);
    }

    /** The method of a {@link #label()} (any case), or a refusal that lists the registered ones. */
    static Variant parse(String text) {
        return Methods.named(text);
    }
}
