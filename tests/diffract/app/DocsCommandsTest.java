package diffract.app;

import org.junit.jupiter.api.Test;
import picocli.CommandLine;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Every {@code ./diffract} command the README and docs/ (every folder) show in code blocks parses as written: its command and
 * options exist and take the values given (a renamed option or an unknown value fails here). Commands with
 * placeholders (N, DIR, ...) or shell variables are left out; the scripts in docs/ run their commands for real.
 */
class DocsCommandsTest {
    /** An upper-case placeholder such as N, DIR or P.gsf standing for a value. */
    private static final Pattern PLACEHOLDER = Pattern.compile("(^|\\s|=)([A-Z]{1,4})(\\.\\w+)?(\\s|$)");

    @Test
    void everyDocumentedCommandParses() throws IOException {
        List<String> commands = new ArrayList<>();
        List<Path> documents = new ArrayList<>(List.of(Path.of("README.md")));
        try (Stream<Path> docs = Files.walk(Path.of("docs"))) { // guide/, design/, measurements/ and their folders
            docs.filter(p -> p.toString().endsWith(".md")).sorted().forEach(documents::add);
        }
        for (Path document : documents) {
            commands.addAll(commandsIn(document));
        }
        assertTrue(commands.size() >= 20, "found only " + commands.size() + " commands");
        List<String> failures = new ArrayList<>();
        for (String command : commands) {
            // a redirection of the output (> FILE) is the shell's, not the command's
            String[] args = command.substring(command.indexOf("./diffract ") + "./diffract ".length())
                    .replaceFirst("\\s>\\s*\\S+\\s*$", "").trim().split("\\s+");
            try {
                Main.commandLine().setCaseInsensitiveEnumValuesAllowed(true).parseArgs(args);
            } catch (CommandLine.ParameterException e) {
                failures.add(command + "\n    " + e.getMessage());
            }
        }
        assertTrue(failures.isEmpty(), String.join("\n", failures));
    }

    /** The {@code ./diffract} lines of the code blocks, continuation lines joined, comments and prompts removed. */
    static List<String> commandsIn(Path document) throws IOException {
        List<String> commands = new ArrayList<>();
        boolean inBlock = false;
        StringBuilder pending = null;
        for (String raw : Files.readAllLines(document, StandardCharsets.UTF_8)) {
            String line = raw.strip();
            if (line.startsWith("```")) {
                inBlock = !inBlock;
                continue;
            }
            boolean indentedCode = raw.startsWith("    ") && line.startsWith("./diffract ");
            if (pending != null) {
                pending.append(' ').append(withoutComment(line));
            } else if ((inBlock || indentedCode) && line.replaceFirst("^\\$ ", "").startsWith("./diffract ")) {
                pending = new StringBuilder(withoutComment(line.replaceFirst("^\\$ ", "")));
            }
            if (pending != null && !pending.toString().endsWith("\\")) {
                String command = pending.toString().strip();
                if (!command.contains("...") && !command.contains("[") && !command.contains("$")
                        && !PLACEHOLDER.matcher(command).find()) {
                    commands.add(command);
                }
                pending = null;
            } else if (pending != null) {
                pending.setLength(pending.length() - 1);
            }
        }
        return commands;
    }

    private static String withoutComment(String line) {
        int hash = line.indexOf(" #");
        return (hash >= 0 ? line.substring(0, hash) : line).strip();
    }
}
