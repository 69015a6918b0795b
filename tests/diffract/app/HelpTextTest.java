package diffract.app;

import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.Model.ArgSpec;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Model.PositionalParamSpec;

import java.lang.reflect.Constructor;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Every command, option and positional parameter says in its help what it is for, and says it from the one catalogue
 * ({@link HelpText}): an option has one text on every command that takes it unless the catalogue gives a command its
 * own, and the catalogue holds nothing that no command shows.
 */
class HelpTextTest {
    @Test
    void everyOptionAndParameterHasADescription() {
        List<String> missing = new ArrayList<>();
        forEachCommand(Main.commandLine().getCommandSpec(), command -> {
            if (!isPicocliOwn(command) && String.join("", command.usageMessage().description()).isBlank()) {
                missing.add(command.qualifiedName());
            }
            for (ArgSpec arg : command.args()) {
                if (String.join("", arg.description()).isBlank()) {
                    missing.add(command.qualifiedName() + " " + name(arg));
                }
            }
        });
        assertEquals(List.of(), missing, "commands, options and parameters without a description");
    }

    /** Without the catalogue no command says anything: no text is written beside its option in the code. */
    @Test
    void everyTextComesFromTheCatalogue() throws ReflectiveOperationException {
        List<String> inline = new ArrayList<>();
        for (CommandLine sub : Main.commandLine().getSubcommands().values()) {
            Object command = sub.getCommandSpec().userObject();
            if (isPicocliOwn(sub.getCommandSpec())) {
                continue;
            }
            Constructor<?> make = command.getClass().getDeclaredConstructor();
            make.setAccessible(true);
            CommandSpec bare = new CommandLine(make.newInstance()).getCommandSpec();
            assertEquals(null, bare.resourceBundle(), "a command alone has no catalogue");
            if (bare.usageMessage().description().length > 0) {
                inline.add(bare.name());
            }
            for (ArgSpec arg : bare.args()) {
                if (!isStandardHelp(arg) && arg.description().length > 0) {
                    inline.add(bare.name() + " " + name(arg));
                }
            }
        }
        assertEquals(List.of(), inline, "texts written in the code instead of help.properties");
    }

    /** Each entry of the catalogue is the text of some command, option or parameter; each value it names exists. */
    @Test
    void theCatalogueHoldsWhatTheCommandsShowAndNoMore() {
        Map<String, String> catalogue = HelpText.catalogue();
        Set<String> used = new TreeSet<>();
        List<String> unresolved = new ArrayList<>();
        forEachCommand(Main.commandLine().getCommandSpec(), command -> {
            if (!isPicocliOwn(command)) {
                used.add(entryOf(command, "usage.description", catalogue));
            }
            for (ArgSpec arg : command.args()) {
                if (!isStandardHelp(arg)) {
                    used.add(entryOf(command, key(arg), catalogue));
                }
                String text = String.join(" ", arg.description());
                if (text.contains("${") || text.contains("null")) {
                    unresolved.add(command.qualifiedName() + " " + name(arg) + ": " + text);
                }
            }
        });
        Set<String> stale = new TreeSet<>(catalogue.keySet());
        stale.removeAll(used);
        assertEquals(Set.of(), stale, "entries of help.properties that no command shows");
        assertEquals(List.of(), unresolved, "texts with a value the catalogue does not have");
        for (String value : HelpText.VALUES.keySet()) {
            assertTrue(catalogue.values().stream().anyMatch(t -> t.contains("${bundle:" + value + "}")),
                    value + " is named by no text: drop it");
        }
    }

    /**
     * A command's own entry for an option says something else than the shared one (else it is the shared one twice),
     * and it belongs to a command that takes the option.
     */
    @Test
    void aCommandsOwnEntryDiffersFromTheSharedOne() {
        Map<String, String> catalogue = HelpText.catalogue();
        Map<String, CommandSpec> commands = new TreeMap<>();
        forEachCommand(Main.commandLine().getCommandSpec(), c -> commands.put(c.qualifiedName("."), c));
        List<String> wrong = new ArrayList<>();
        for (Map.Entry<String, String> e : catalogue.entrySet()) {
            String key = e.getKey();
            if (!key.startsWith("diffract.") || key.endsWith(".usage.description")) {
                continue;
            }
            int dot = key.lastIndexOf('.');
            CommandSpec command = commands.get(key.substring(0, dot));
            String name = key.substring(dot + 1);
            if (command == null || command.args().stream().noneMatch(a -> key(a).equals(name))) {
                wrong.add(key + ": no such command or option");
            } else if (e.getValue().equals(catalogue.get(name))) {
                wrong.add(key + ": the same as " + name);
            }
        }
        assertEquals(List.of(), wrong);
        assertFalse(catalogue.containsKey("usage.description"), "a text every command without its own would show");
    }

    /** The entry picocli shows for a command's key: the command's own if there is one, else the shared one. */
    private static String entryOf(CommandSpec command, String key, Map<String, String> catalogue) {
        String own = command.qualifiedName(".") + "." + key;
        return catalogue.containsKey(own) ? own : key;
    }

    private static String key(ArgSpec arg) {
        if (arg instanceof PositionalParamSpec) {
            return arg.descriptionKey();
        }
        return ((OptionSpec) arg).longestName().replaceFirst("^-+", "");
    }

    private static String name(ArgSpec arg) {
        return arg instanceof OptionSpec option ? option.longestName() : arg.paramLabel();
    }

    private static boolean isStandardHelp(ArgSpec arg) {
        return arg instanceof OptionSpec option && (option.usageHelp() || option.versionHelp());
    }

    /** picocli's own help command, whose texts are picocli's. */
    private static boolean isPicocliOwn(CommandSpec command) {
        return command.userObject() instanceof CommandLine.HelpCommand;
    }

    private static void forEachCommand(CommandSpec command, java.util.function.Consumer<CommandSpec> action) {
        action.accept(command);
        for (CommandLine sub : command.subcommands().values()) {
            forEachCommand(sub.getCommandSpec(), action);
        }
    }
}
