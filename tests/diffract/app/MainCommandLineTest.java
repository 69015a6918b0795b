package diffract.app;

import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;

import java.util.List;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A run of one command builds that command alone, and reads its options exactly as the whole command line does; a
 * line that names no command (or help, or a misspelt one) gets every command.
 */
class MainCommandLineTest {
    private static final Set<String> EVERY = Main.commandLine().getSubcommands().keySet();

    @Test
    void aCommandIsBuiltAloneAndTheRestGetEveryCommand() {
        assertTrue(EVERY.containsAll(List.of("brdfmap", "render", "bench", "merge", "submit", "help", "patch")),
                EVERY.toString());
        assertEquals(Set.of("brdfmap"), Main.commandLine("brdfmap", "--size", "8").getSubcommands().keySet());
        assertEquals(Set.of("brdfmap"), Main.commandLine("--debug", "brdfmap").getSubcommands().keySet());
        assertEquals(Set.of("bench"), Main.commandLine("bench", "--help").getSubcommands().keySet());
        assertEquals(EVERY, Main.commandLine("help", "brdfmap").getSubcommands().keySet());
        assertEquals(EVERY, Main.commandLine("brdfmpa").getSubcommands().keySet()); // picocli suggests the others
        assertEquals(EVERY, Main.commandLine("--help").getSubcommands().keySet());
        assertEquals(EVERY, Main.commandLine().getSubcommands().keySet());
    }

    @Test
    void theLoneCommandHasTheSameOptionsAndSettings() {
        for (String name : EVERY) {
            if (name.equals("help")) {
                continue;
            }
            CommandSpec whole = Main.commandLine().getSubcommands().get(name).getCommandSpec();
            CommandSpec alone = Main.commandLine(name).getSubcommands().get(name).getCommandSpec();
            assertEquals(forms(whole), forms(alone), name);
            assertEquals(whole.parser().caseInsensitiveEnumValuesAllowed(),
                    alone.parser().caseInsensitiveEnumValuesAllowed(), name);
            assertTrue(alone.parser().caseInsensitiveEnumValuesAllowed(), name);
            assertEquals(whole.usageMessage().footer().length, alone.usageMessage().footer().length, name);
        }
    }

    @Test
    void theInheritedDebugOptionReachesTheLoneCommand() {
        CommandLine.ParseResult parsed = Main.commandLine("brdfmap").parseArgs("brdfmap", "--debug", "--size", "8");
        assertTrue(parsed.subcommand().hasMatchedOption("--debug"));
    }

    private static List<String> forms(CommandSpec command) {
        return command.options().stream().map(OptionSpec::longestName).sorted().toList();
    }
}
