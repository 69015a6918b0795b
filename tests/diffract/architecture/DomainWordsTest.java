package diffract.architecture;

import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Messages below the command line name quantities, not options: no string literal of the domain, the precompute,
 * the engine, the GPU materials, the pipeline or the scene reader holds a flag such as {@code --terms}. The command
 * line maps a quantity to its option (OptionNames), the scene reader to its key.
 */
class DomainWordsTest {
    private static final Pattern STRING = Pattern.compile("\"((?:[^\"\\\\]|\\\\.)*)\"");
    private static final Pattern FLAG = Pattern.compile("(^|[\\s(])--[a-z]");

    @Test
    void noFlagNamesInDomainMessages() throws IOException {
        List<String> found = new ArrayList<>();
        for (String pkg : List.of("util", "colour", "geometry", "lighting", "optics", "precompute", "jrtr", "render",
                "pipeline", "scene")) {
            try (Stream<Path> files = Files.walk(Path.of("src", "diffract", pkg))) {
                for (Path file : files.filter(f -> f.toString().endsWith(".java")).toList()) {
                    List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
                    for (int i = 0; i < lines.size(); i++) {
                        String code = lines.get(i).strip();
                        if (code.startsWith("*") || code.startsWith("//") || code.startsWith("/*")) {
                            continue;
                        }
                        Matcher m = STRING.matcher(code);
                        while (m.find()) {
                            if (FLAG.matcher(m.group(1)).find()) {
                                found.add(file + ":" + (i + 1) + ": " + m.group());
                            }
                        }
                    }
                }
            }
        }
        assertTrue(found.isEmpty(), "flag names in domain messages:\n" + String.join("\n", found));
    }
}
