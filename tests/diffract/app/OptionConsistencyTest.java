package diffract.app;

import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * An option has one form on every command that takes it: the same type of value and the same placeholder in the help
 * (a range or a default that differs is said in that help). The exceptions name what differs and why.
 */
class OptionConsistencyTest {
    /** Options whose value differs between commands by design. */
    static final Map<String, String> DIFFERS_ON_PURPOSE = Map.of(
            "--output", "each command writes its own kind of file or folder",
            "--terms", "bench's sweep takes a list of N where the others take one",
            "--exposure", "a BRDF map may take auto (its brightest order); a scene is exposed radiometrically",
            "--size", "bench's sweep and a BRDF map are square (S); pictures are WxH",
            "--from", "convert-terms converts a folder of terms; patch writes what it reads from a height-field file");

    @Test
    void everySharedOptionTakesTheSameValueEverywhere() {
        Map<String, TreeSet<String>> forms = new TreeMap<>();
        Map<String, List<String>> where = new TreeMap<>();
        walk(Main.commandLine().getCommandSpec(), forms, where);
        List<String> inconsistent = new ArrayList<>();
        forms.forEach((name, variants) -> {
            if (variants.size() > 1 && !DIFFERS_ON_PURPOSE.containsKey(name)) {
                inconsistent.add(name + " " + variants + " on " + where.get(name));
            }
        });
        assertEquals(List.of(), inconsistent);
        // the exceptions are real ones: each is shared and differs today
        for (String name : DIFFERS_ON_PURPOSE.keySet()) {
            assertTrue(forms.containsKey(name) && forms.get(name).size() > 1, name + " no longer differs: drop it");
        }
    }

    private static void walk(CommandSpec command, Map<String, TreeSet<String>> forms, Map<String, List<String>> where) {
        for (OptionSpec option : command.options()) {
            if (option.usageHelp() || option.versionHelp()) {
                continue;
            }
            String name = option.longestName();
            forms.computeIfAbsent(name, k -> new TreeSet<>()).add(boxed(option.type()).getSimpleName() + " "
                    + option.paramLabel());
            where.computeIfAbsent(name, k -> new ArrayList<>()).add(command.name());
        }
        for (CommandLine sub : command.subcommands().values()) {
            walk(sub.getCommandSpec(), forms, where);
        }
    }

    private static Class<?> boxed(Class<?> type) {
        if (!type.isPrimitive()) {
            return type;
        }
        return type == double.class ? Double.class : type == int.class ? Integer.class : type == boolean.class
                ? Boolean.class : type == long.class ? Long.class : type == float.class ? Float.class : type;
    }
}
