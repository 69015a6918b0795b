package diffract.optics;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The registry of diffraction methods ({@link Variant}), by label: the built-in ones, then those registered by
 * {@link #register} (a plugin, or a test's toy method), in that order. The commands' {@code --variant}, the scene
 * files' {@code material.variant} and the bench's sweep ask it.
 */
public final class Methods {
    private static final Map<String, Variant> BY_LABEL = new LinkedHashMap<>();

    private static final Variant[] BUILT_IN = {Variant.REFERENCE, Variant.FLSS, Variant.NMM, Variant.PQ,
            Variant.BAKED, Variant.LOBES};

    static {
        for (Variant v : BUILT_IN) {
            BY_LABEL.put(v.label(), v);
        }
    }

    private Methods() {
    }

    /**
     * Adds {@code method} under its label; registering the same instance again does nothing, another method under a
     * label already taken is refused.
     */
    public static synchronized void register(Variant method) {
        String key = key(method.label());
        Variant present = BY_LABEL.get(key);
        if (present != null && present != method) {
            throw new IllegalArgumentException("a method is registered as '" + key + "' already: " + present);
        }
        if (!key.equals(method.label()) || key.isEmpty() || !key.matches("[a-z][a-z0-9-]*")) {
            throw new IllegalArgumentException("a method's label is lower-case letters, digits and hyphens, got '"
                    + method.label() + "'");
        }
        BY_LABEL.put(key, method);
    }

    /** Removes a method {@link #register} added (a test's toy method, after its test); the built-in ones stay. */
    public static synchronized void unregister(Variant method) {
        for (Variant builtIn : BUILT_IN) {
            if (builtIn == method) {
                throw new IllegalArgumentException("the built-in method " + method.label() + " stays registered");
            }
        }
        BY_LABEL.remove(key(method.label()), method);
    }

    /** Every registered method, the built-in ones first. */
    public static synchronized List<Variant> all() {
        return new ArrayList<>(BY_LABEL.values());
    }

    /** The method of a label (any case), or a refusal that lists the registered ones. */
    public static synchronized Variant named(String text) {
        Variant v = BY_LABEL.get(key(text));
        if (v == null) {
            throw new InvalidSettingException(Quantity.VARIANT, "unknown variant '" + text + "': use "
                    + listed(m -> true, "or"));
        }
        return v;
    }

    /**
     * The labels of the registered methods that {@code which} accepts, as a sentence lists them: "flss, nmm and pq"
     * with {@code conjunction} "and".
     */
    public static synchronized String listed(java.util.function.Predicate<Variant> which, String conjunction) {
        List<String> labels = BY_LABEL.values().stream().filter(which).map(Variant::label).toList();
        if (labels.size() <= 1) {
            return String.join("", labels);
        }
        return String.join(", ", labels.subList(0, labels.size() - 1)) + " " + conjunction + " "
                + labels.get(labels.size() - 1);
    }

    private static String key(String label) {
        return label.trim().toLowerCase(Locale.ROOT);
    }
}
