package diffract.scene;

import diffract.util.UserInputException;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * Mutated scene text (characters deleted, inserted or replaced; values swapped for other JSON values) is either a
 * scene or a one-line {@link UserInputException} naming the file: never another exception.
 */
class SceneFuzzTest {
    private static final List<String> SCENES;
    private static final List<String> VALUES = List.of("null", "true", "-1", "0", "1e309", "-0.0", "\"\"", "\"x\"",
            "[]", "{}", "[1, 2]", "[0, 0, 0]", "[1e308, 1e308, 1e308]", "123456789012345678901234567890", "0.5",
            "{\"file\": \"/\"}", "{\"project\": [0, 0, 0]}", "\"explicit\"", "\"brdfMap\"", "4097", "1e-300");

    static {
        try {
            SCENES = List.of(Files.readString(SceneFileTest.SCENES.resolve("snake-elaphe.json")),
                    Files.readString(SceneFileTest.SCENES.resolve("blazed-grating-plane.json")),
                    SceneFileTest.valid(",\n \"tolerance\": 0.01, \"pigmentation\": {\"file\": \"x.png\"}"));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Provide
    Arbitrary<String> mutatedScenes() {
        Arbitrary<String> scene = Arbitraries.of(SCENES);
        Arbitrary<Integer> position = Arbitraries.integers().between(0, 100_000);
        Arbitrary<String> characters = Arbitraries.strings().withChars("{}[]\":,.-+eE0123456789 \nabcxyz\\")
                .ofMinLength(0).ofMaxLength(4);
        Arbitrary<String> edit = Combinators.combine(scene, position, position, characters, Arbitraries.of(VALUES))
                .as((text, a, b, inserted, value) -> {
                    int from = a % (text.length() + 1);
                    int to = Math.min(text.length(), from + b % 6);
                    // half the time, replace a value after a colon by another JSON value: deep type errors
                    int colon = text.indexOf(':', from);
                    if (b % 2 == 0 && colon > 0) {
                        int end = colon + 1;
                        while (end < text.length() && ",}\n".indexOf(text.charAt(end)) < 0) {
                            end++;
                        }
                        return text.substring(0, colon + 1) + " " + value + text.substring(end);
                    }
                    return text.substring(0, from) + inserted + text.substring(to);
                });
        return edit;
    }

    @Property(tries = 400)
    void mutatedScenesFailOnlyWithOneLineUserErrors(@ForAll("mutatedScenes") String text) {
        Path base = Path.of("target").toAbsolutePath();
        try {
            SceneFile.parse(text, "fuzz.json", base, base.resolve("fuzz.json"));
        } catch (UserInputException e) {
            if (!e.getMessage().startsWith("fuzz.json:") || e.getMessage().contains("\n")) {
                throw new AssertionError("not a one-line located message: " + e.getMessage() + "\nfor\n" + text);
            }
        }
    }
}
