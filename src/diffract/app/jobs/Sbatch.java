package diffract.app.jobs;

import diffract.util.UserInputException;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/**
 * Slurm's {@code sbatch}, run on a job script: {@code --parsable} makes it print the job's id alone as soon as the
 * scheduler accepted it; with {@code --wait} it then returns when the whole array has ended, with the highest exit code
 * of its tasks.
 */
public final class Sbatch {
    /** The program that submits; a test names one that is not there. */
    public static String program = "sbatch";

    /** How sbatch ended: the job's id (null if it was never accepted), its exit code and what it said on stderr. */
    public record Result(String jobId, int exitCode, String errors) {
    }

    private Sbatch() {
    }

    /**
     * Submits {@code script}; {@code submitted} hears the job's id as soon as sbatch prints it. Refuses, in one line,
     * a machine without sbatch and a script the scheduler does not accept.
     */
    public static Result submit(Path script, boolean wait, Consumer<String> submitted) throws IOException,
            InterruptedException {
        List<String> command = new ArrayList<>(List.of(program, "--parsable"));
        if (wait) {
            command.add("--wait");
        }
        command.add(script.toString());
        // what sbatch says on stderr goes to a file, read once it has ended
        Path errorFile = Files.createTempFile("diffract-sbatch-", ".err");
        Process p;
        try {
            p = new ProcessBuilder(command).redirectError(errorFile.toFile()).start();
        } catch (IOException e) {
            Files.deleteIfExists(errorFile);
            throw new UserInputException(program + " not found: --slurm submits with Slurm's sbatch, on a machine that "
                    + "can submit jobs (a cluster's login node); or run the pieces here with --local J");
        }
        p.getOutputStream().close();
        String jobId = null;
        try (BufferedReader out = new BufferedReader(new InputStreamReader(p.getInputStream(),
                StandardCharsets.UTF_8))) {
            for (String line = out.readLine(); line != null; line = out.readLine()) {
                // the id, or id;cluster on a federation
                String id = line.strip().split(";", 2)[0];
                if (jobId == null && id.matches("[0-9]+")) {
                    jobId = id;
                    submitted.accept(jobId);
                }
            }
        } finally {
            if (p.isAlive()) {
                p.destroy(); // an interrupted submit stops waiting; the array runs on
            }
        }
        int code = p.waitFor();
        String errors = Files.readString(errorFile, StandardCharsets.UTF_8);
        Files.deleteIfExists(errorFile);
        Result result = new Result(jobId, code, errors.strip());
        if (jobId == null) {
            throw new UserInputException("sbatch did not accept " + script + " (exit code " + code + "): "
                    + lastLine(result.errors()));
        }
        return result;
    }

    /** The last line a program printed, or that it printed none. */
    public static String lastLine(String output) {
        String[] lines = output.strip().split("\n");
        return lines.length == 0 || lines[lines.length - 1].isBlank() ? "(no output)" : lines[lines.length - 1].strip();
    }
}
