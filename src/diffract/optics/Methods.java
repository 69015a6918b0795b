package diffract.optics;

import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;

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
            Variant.BAKED, Variant.LOBES, Variant.RIGOROUS};

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

    /**
     * The method of a label (any case), or of a label with its parameter, {@code label(of=inner)} (a method that
     * takes another, {@link Variant#of}), or a refusal that lists the registered ones.
     */
    public static Variant named(String text) {
        java.util.regex.Matcher m = WITH_PARAMETER.matcher(text.trim());
        if (m.matches()) {
            return registered(m.group(1)).of(named(m.group(2)));
        }
        return registered(text);
    }

    /** {@code label(of=inner)}, the inner one possibly with a parameter of its own. */
    private static final java.util.regex.Pattern WITH_PARAMETER = java.util.regex.Pattern.compile(
            "([A-Za-z][A-Za-z0-9-]*)\\s*\\(\\s*of\\s*=\\s*(.+?)\\s*\\)");

    private static synchronized Variant registered(String text) {
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

    /**
     * The roles a method plays for the commands, the viewer and the bench, and the method that plays each: the one
     * table of which method a command draws or measures when none is named.
     */
    public enum Role {
        /** What accuracy is measured against: {@code brdfmap}'s default, the reference maps of the bench and suite. */
        EXACT(Variant.REFERENCE),
        /**
         * What the scalar model itself is measured against: Maxwell's equations on periodic patches (the validity map,
         * the viewer's second yardstick).
         */
        MAXWELL(Variant.RIGOROUS),
        /** The thesis' shader: the bench's speed baseline and the thesis' configuration. */
        THESIS(Variant.FLSS),
        /**
         * Cheap per fragment with nothing to bake: the viewer's preview, what it draws when a bake fails, and what a
         * scene draws under a point light when its method refuses the patch.
         */
        FALLBACK(Variant.FLSS),
        /** Filters extended lights and pixel footprints: the default of scenes and {@code render}. */
        FILTERING(Variant.LOBES),
        /** One lookup per fragment: the default of {@code view}. */
        TABLE(Variant.BAKED);

        private final Variant method;

        Role(Variant method) {
            this.method = method;
        }

        /** The method that plays this role. */
        public Variant method() {
            return method;
        }
    }

    private static String key(String label) {
        return label.trim().toLowerCase(Locale.ROOT);
    }
}
