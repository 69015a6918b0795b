package diffract.app.options;

import diffract.app.Main;
import diffract.optics.settings.Quantity;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

import java.util.HashSet;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertTrue;

/** Every quantity a message can name has an option, and that option exists on the command line. */
class OptionNamesTest {
    @Test
    void everyQuantityHasAnOptionThatACommandDeclares() {
        CommandLine cli = Main.commandLine();
        Set<String> declared = new HashSet<>();
        for (CommandLine sub : cli.getSubcommands().values()) {
            sub.getCommandSpec().options().forEach(o -> declared.addAll(java.util.List.of(o.names())));
        }
        for (Quantity q : Quantity.values()) {
            String flag = OptionNames.of(q);
            assertTrue(declared.contains(flag), q + ": no command declares " + flag);
        }
    }

    @Test
    void theSameOptionMeansTheSameOnEveryCommand() {
        CommandLine cli = Main.commandLine();
        for (String shared : new String[] {"--terms", "--variant", "--window-radius", "--coherence-length",
            "--lambda-step", "--patch", "--synthetic"}) {
            Set<String> labels = new HashSet<>();
            for (String command : new String[] {"brdfmap", "view", "render"}) {
                labels.add(cli.getSubcommands().get(command).getCommandSpec().findOption(shared).paramLabel()
                        + " " + String.join(" ", cli.getSubcommands().get(command).getCommandSpec()
                        .findOption(shared).description()));
            }
            assertTrue(labels.size() == 1, shared + " differs between brdfmap, view and render: " + labels);
        }
    }
}
