package diffract.scene;

import diffract.util.UserInputException;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * One JSON object of a scene file being read: typed, range-checked access to its keys, each problem thrown as
 * one line {@code FILE:LINE: key.path: what is wrong (and the fix)}. Every key read is remembered, so
 * {@link #finish()} can refuse the keys nobody asked for (a typo would otherwise be ignored silently).
 */
final class SceneObject {
    private final SceneSource source;
    private final String path;
    private final int line;
    private final Map<String, JsonTree.Located> members;
    private final Set<String> known = new LinkedHashSet<>();

    /** Where a scene's text came from: the file named in messages and the folder relative paths start from. */
    record SceneSource(String displayName, Path baseDirectory) {
    }

    @SuppressWarnings("unchecked")
    private SceneObject(SceneSource source, String path, JsonTree.Located node) {
        this.source = source;
        this.path = path;
        this.line = node.line();
        this.members = (Map<String, JsonTree.Located>) node.value();
    }

    /** The document's root, which must be an object. */
    static SceneObject root(SceneSource source, JsonTree.Located node) {
        if (!(node.value() instanceof Map)) {
            throw problem(source, node.line(), "(scene)", "must be a JSON object { ... }, got " + node.typeName());
        }
        return new SceneObject(source, "", node);
    }

    static UserInputException problem(SceneSource source, int line, String keyPath, String what) {
        return new UserInputException(source.displayName() + ":" + line + ": " + escapeControls(keyPath) + ": "
                + escapeControls(what));
    }

    /**
     * Keys and values quoted from the file may hold JSON-escaped control characters ("\n" in a key); written as
     * escapes again, so a message stays one line whatever the file holds (SceneFuzzTest found a key with a newline).
     */
    static String escapeControls(String text) {
        StringBuilder b = new StringBuilder(text.length());
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            switch (c) {
                case '\n' -> b.append("\\n");
                case '\r' -> b.append("\\r");
                case '\t' -> b.append("\\t");
                default -> {
                    if (c < 0x20 || c == 0x7f || c == 0x2028 || c == 0x2029 || c == 0x85) {
                        b.append(String.format("\\u%04x", (int) c));
                    } else {
                        b.append(c);
                    }
                }
            }
        }
        return b.toString();
    }

    UserInputException problem(String key, String what) {
        JsonTree.Located node = members.get(key);
        return problem(source, node == null ? line : node.line(), keyPath(key), what);
    }

    String keyPath(String key) {
        return path.isEmpty() ? key : path + "." + key;
    }

    SceneSource source() {
        return source;
    }

    int line() {
        return line;
    }

    boolean has(String key) {
        known.add(key);
        return members.containsKey(key);
    }

    /** The raw value of a key (after {@link #has}), for keys that take more than one type. */
    JsonTree.Located raw(String key) {
        known.add(key);
        return members.get(key);
    }

    private JsonTree.Located require(String key, String expected) {
        known.add(key);
        JsonTree.Located node = members.get(key);
        if (node == null) {
            throw problem(source, line, keyPath(key), "missing; add \"" + key + "\": " + expected);
        }
        return node;
    }

    SceneObject object(String key) {
        JsonTree.Located node = require(key, "{ ... }");
        if (!(node.value() instanceof Map)) {
            throw problem(key, "must be an object { ... }, got " + node.typeName());
        }
        return new SceneObject(source, keyPath(key), node);
    }

    /** The object under {@code key} as a child reader (for values already known to be objects). */
    SceneObject child(String key, JsonTree.Located node) {
        return new SceneObject(source, keyPath(key), node);
    }

    double number(String key, Range range) {
        JsonTree.Located node = require(key, range.example());
        if (!(node.value() instanceof Double)) {
            throw problem(key, "must be a number " + range.describe() + ", got " + node.typeName());
        }
        double value = (Double) node.value();
        if (!range.contains(value)) {
            throw problem(key, "must be " + range.describe() + ", got " + format(value));
        }
        return value;
    }

    double number(String key, Range range, double defaultValue) {
        return has(key) ? number(key, range) : defaultValue;
    }

    int integer(String key, Range range) {
        double value = number(key, range);
        if (value != Math.rint(value)) {
            throw problem(key, "must be a whole number " + range.describe() + ", got " + format(value));
        }
        return (int) value;
    }

    int integer(String key, Range range, int defaultValue) {
        return has(key) ? integer(key, range) : defaultValue;
    }

    long wholeNumber(String key, long defaultValue) {
        if (!has(key)) {
            return defaultValue;
        }
        double value = number(key, Range.any());
        if (value != Math.rint(value) || Math.abs(value) > 1L << 53) {
            throw problem(key, "must be a whole number, got " + format(value));
        }
        return (long) value;
    }

    boolean bool(String key, boolean defaultValue) {
        if (!has(key)) {
            return defaultValue;
        }
        JsonTree.Located node = members.get(key);
        if (!(node.value() instanceof Boolean)) {
            throw problem(key, "must be true or false, got " + node.typeName());
        }
        return (Boolean) node.value();
    }

    /** One of {@code choices}, compared exactly (they are documented spellings). */
    String choice(String key, List<String> choices) {
        JsonTree.Located node = require(key, "\"" + choices.get(0) + "\"");
        if (!(node.value() instanceof String)) {
            throw problem(key, "must be one of " + quoted(choices) + ", got " + node.typeName());
        }
        String value = (String) node.value();
        if (!choices.contains(value)) {
            throw problem(key, "unknown value \"" + value + "\"" + suggestion(value, choices) + "; use one of "
                    + quoted(choices));
        }
        return value;
    }

    String choice(String key, List<String> choices, String defaultValue) {
        return has(key) ? choice(key, choices) : defaultValue;
    }

    /** Three finite numbers [x, y, z]. */
    double[] vector3(String key) {
        JsonTree.Located node = require(key, "[x, y, z]");
        return vector3(key, node);
    }

    double[] vector3(String key, double[] defaultValue) {
        return has(key) ? vector3(key) : defaultValue.clone();
    }

    double[] vector3(String key, JsonTree.Located node) {
        if (node.value() instanceof List<?> items && items.size() == 3) {
            double[] v = new double[3];
            for (int k = 0; k < 3; k++) {
                Object item = ((JsonTree.Located) items.get(k)).value();
                if (!(item instanceof Double d) || !Double.isFinite(d)) {
                    break;
                }
                v[k] = (Double) item;
                if (k == 2) {
                    return v;
                }
            }
        }
        throw problem(key, "must be an array of three numbers [x, y, z], got "
                + (node.value() instanceof List<?> l ? "an array of " + l.size() + " items" : node.typeName()));
    }

    /**
     * A positive number or an array of two, [u, v], within {@code range}: one number stands for both; 0 when absent.
     */
    double[] pair(String key, Range range) {
        if (!has(key)) {
            return new double[2];
        }
        JsonTree.Located node = raw(key);
        if (node.value() instanceof Double) {
            double value = number(key, range);
            return new double[] {value, value};
        }
        if (node.value() instanceof List<?> items && items.size() == 2
                && ((JsonTree.Located) items.get(0)).value() instanceof Double a
                && ((JsonTree.Located) items.get(1)).value() instanceof Double b && range.contains(a)
                && range.contains(b)) {
            return new double[] {a, b};
        }
        throw problem(key, "must be a number or an array of two numbers [u, v], each " + range.describe() + ", got "
                + (node.value() instanceof List<?> l ? "an array of " + l.size() + " items" : node.typeName()));
    }

    /** A non-zero vector [x, y, z]. */
    double[] direction(String key, JsonTree.Located node) {
        double[] v = vector3(key, node);
        if (!(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] > 1e-24)) {
            throw problem(key, "must be a non-zero direction, got [0, 0, 0]");
        }
        return v;
    }

    double[] direction(String key) {
        return direction(key, require(key, "[x, y, z]"));
    }

    /** A path relative to the scene file's folder (or absolute) that must name an existing file. */
    Path existingFile(String key) {
        JsonTree.Located node = require(key, "\"FILE\"");
        if (!(node.value() instanceof String text) || text.isBlank()) {
            throw problem(key, "must be a file name (a string), got " + node.typeName());
        }
        Path file;
        try {
            file = source.baseDirectory().resolve(text).normalize();
        } catch (java.nio.file.InvalidPathException e) {
            throw problem(key, "\"" + text + "\" is not a valid path: " + e.getReason());
        }
        if (!Files.isRegularFile(file)) {
            throw problem(key, "file " + file + " not found (paths are relative to the scene file's folder "
                    + source.baseDirectory() + ")");
        }
        return file;
    }

    /** Refuses every key that was not asked for, suggesting the nearest known key. */
    void finish() {
        for (String key : members.keySet()) {
            if (!known.contains(key)) {
                throw problem(key, "unknown key" + suggestion(key, List.copyOf(known)) + "; known keys here: "
                        + String.join(", ", known));
            }
        }
    }

    static String suggestion(String given, List<String> candidates) {
        String best = null;
        int bestDistance = Integer.MAX_VALUE;
        for (String candidate : candidates) {
            int d = editDistance(given.toLowerCase(Locale.ROOT), candidate.toLowerCase(Locale.ROOT));
            if (d < bestDistance) {
                bestDistance = d;
                best = candidate;
            }
        }
        // a suggestion further than half the word away is noise, not help
        return best != null && bestDistance <= Math.max(2, given.length() / 2) ? " (did you mean \"" + best + "\"?)" : "";
    }

    static int editDistance(String a, String b) {
        int[] previous = new int[b.length() + 1];
        int[] current = new int[b.length() + 1];
        for (int j = 0; j <= b.length(); j++) {
            previous[j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            current[0] = i;
            for (int j = 1; j <= b.length(); j++) {
                int substitution = previous[j - 1] + (a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1);
                current[j] = Math.min(substitution, Math.min(previous[j] + 1, current[j - 1] + 1));
            }
            int[] swap = previous;
            previous = current;
            current = swap;
        }
        return previous[b.length()];
    }

    private static String quoted(List<String> choices) {
        return "\"" + String.join("\", \"", choices) + "\"";
    }

    static String format(double value) {
        return value == Math.rint(value) && Math.abs(value) < 1e15 ? Long.toString((long) value)
                : Double.toString(value);
    }

    /** An allowed interval of numbers, as messages state it. */
    record Range(double min, boolean minOpen, double max, boolean maxOpen) {
        static Range any() {
            return new Range(-Double.MAX_VALUE, false, Double.MAX_VALUE, false);
        }

        static Range positive() {
            return new Range(0, true, Double.MAX_VALUE, false);
        }

        static Range closed(double min, double max) {
            return new Range(min, false, max, false);
        }

        static Range open(double min, double max) {
            return new Range(min, true, max, true);
        }

        /** (min, max]. */
        static Range above(double min, double max) {
            return new Range(min, true, max, false);
        }

        boolean contains(double v) {
            return Double.isFinite(v) && (minOpen ? v > min : v >= min) && (maxOpen ? v < max : v <= max);
        }

        String describe() {
            if (min == -Double.MAX_VALUE) {
                return "(a finite number)";
            }
            if (max == Double.MAX_VALUE) {
                return minOpen ? "> " + format(min) : ">= " + format(min);
            }
            return "in " + (minOpen ? "(" : "[") + format(min) + ", " + format(max) + (maxOpen ? ")" : "]");
        }

        String example() {
            return min == -Double.MAX_VALUE ? "0" : format(Math.max(min, Math.min(max, minOpen ? min + 1 : min)));
        }
    }
}
