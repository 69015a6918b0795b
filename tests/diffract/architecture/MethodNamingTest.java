package diffract.architecture;

import diffract.optics.Methods;
import diffract.optics.Variant;
import diffract.render.GpuMethod;
import diffract.render.GpuMethods;
import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A method is one class: outside the methods' own classes (those implementing {@link Variant} or {@link GpuMethod})
 * and their registries ({@link Methods}, with the table of roles, and {@link GpuMethods}), no Java file names two or
 * more of the built-in methods. A file names a method by its constant ({@code Variant.FLSS}), its label as a string
 * literal ({@code "flss"}) or its classes ({@code FlssMethod}, {@code FlssGpu}). What differs between methods is asked
 * of the method (its capabilities) or of a role ({@link Methods.Role}), so a new method touches no other file.
 */
class MethodNamingTest {
    private static final List<String> BUILT_IN = List.of("reference", "flss", "nmm", "pq", "baked", "lobes",
            "rigorous");

    @Test
    void noFileOutsideTheMethodsNamesTwoOfThem() throws IOException {
        List<String> found = new ArrayList<>();
        int read = 0;
        try (Stream<Path> files = Files.walk(Path.of("src", "diffract"))) {
            for (Path file : files.filter(f -> f.toString().endsWith(".java")).sorted().toList()) {
                if (isMethodOrRegistry(file)) {
                    continue;
                }
                read++;
                Set<String> named = methodsNamed(Files.readString(file, StandardCharsets.UTF_8));
                if (named.size() >= 2) {
                    found.add(file + ": " + named);
                }
            }
        }
        assertTrue(read > 250, "read " + read + " files");
        assertTrue(found.isEmpty(), "files that name two or more methods:\n" + String.join("\n", found));
    }

    /** The check itself catches each way of naming a method, and counts a method once however often it is named. */
    @Test
    void theCheckSeesEveryWayOfNamingAMethod() {
        assertEquals(Set.of("flss", "lobes"), methodsNamed("x = s.variant() == Variant.FLSS ? Variant.LOBES : y;"));
        assertEquals(Set.of("baked", "pq"), methodsNamed("Variant.parse(\"baked\"); new PqGpu();"));
        assertEquals(Set.of("reference", "nmm"), methodsNamed("ReferenceMethod r; NmmMethod n; NmmMethod m;"));
        assertEquals(Set.of(), methodsNamed("Methods.Role.THESIS.method(); \"the lobes of a grating\"; flssLike"));
        assertEquals(Set.of("lobes"), methodsNamed("Variant.LOBES; \"lobes\"; LobesGpu.LIGHT_NODES_MAX"));
    }

    private static Set<String> methodsNamed(String source) {
        Set<String> named = new TreeSet<>();
        for (String label : BUILT_IN) {
            String constant = label.toUpperCase(Locale.ROOT);
            String cls = Character.toUpperCase(label.charAt(0)) + label.substring(1);
            Pattern naming = Pattern.compile("\\bVariant\\." + constant + "\\b|\"" + label + "\"|\\b" + cls
                    + "(Method|Gpu)\\b");
            if (naming.matcher(source).find()) {
                named.add(label);
            }
        }
        return named;
    }

    private static boolean isMethodOrRegistry(Path file) {
        if (file.getFileName().toString().equals("package-info.java")) {
            return false;
        }
        String name = Path.of("src").relativize(file).toString().replace(java.io.File.separatorChar, '.')
                .replaceFirst("\\.java$", "");
        try {
            Class<?> c = Class.forName(name, false, MethodNamingTest.class.getClassLoader());
            return Variant.class.isAssignableFrom(c) || GpuMethod.class.isAssignableFrom(c) || c == Methods.class
                    || c == GpuMethods.class;
        } catch (ClassNotFoundException e) {
            throw new AssertionError("no class for " + file, e);
        }
    }
}
