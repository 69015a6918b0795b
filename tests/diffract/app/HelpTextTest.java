package diffract.app;

import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.Model.ArgSpec;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** Every option and positional parameter of every command says in its help what it is for. */
class HelpTextTest {
    @Test
    void everyOptionAndParameterHasADescription() {
        List<String> missing = new ArrayList<>();
        collect(Main.commandLine().getCommandSpec(), missing);
        assertEquals(List.of(), missing, "options and parameters without a description");
    }

    private static void collect(CommandSpec command, List<String> missing) {
        for (ArgSpec arg : command.args()) {
            if (String.join("", arg.description()).isBlank()) {
                String name = arg instanceof OptionSpec option ? option.longestName() : arg.paramLabel();
                missing.add(command.qualifiedName() + " " + name);
            }
        }
        for (CommandLine sub : command.subcommands().values()) {
            collect(sub.getCommandSpec(), missing);
        }
    }
}
