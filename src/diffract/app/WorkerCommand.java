package diffract.app;

import com.fasterxml.jackson.databind.ObjectMapper;
import diffract.util.UserInputException;
import picocli.CommandLine.Command;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.Callable;

/**
 * {@code diffract worker} (hidden): the process of one of {@code submit --local}'s workers. It reads commands from
 * standard input, one JSON array of arguments a line, and runs each in this process, one after another; after each it
 * writes {@link #DONE} and the command's exit code on a line of its own. A worker so pays Java's start and the
 * compilation of the code its pieces run once, not once per piece.
 */
@Command(name = "worker", hidden = true)
final class WorkerCommand implements Callable<Integer> {
    /** What starts the line after a command's output: a NUL, so that no output of a command can look like it. */
    static final String DONE = "\u0000diffract worker: exit ";

    private static final ObjectMapper JSON = new ObjectMapper();

    @Override
    public Integer call() throws IOException {
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        for (String line = in.readLine(); line != null; line = in.readLine()) {
            if (line.isBlank()) {
                continue;
            }
            String[] args;
            try {
                args = JSON.readValue(line, String[].class);
            } catch (IOException e) {
                throw new UserInputException("worker: not a JSON array of arguments: " + line);
            }
            int code = Main.execute(args);
            System.err.flush(); // the command's output before the line that ends it
            System.out.println(DONE + code);
            System.out.flush();
        }
        return 0;
    }
}
