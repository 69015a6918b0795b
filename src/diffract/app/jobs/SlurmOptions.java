package diffract.app.jobs;

import diffract.util.UserInputException;
import picocli.CommandLine.Option;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * {@code submit --slurm}: the pieces as one Slurm job array, and what its tasks ask the scheduler for. Each option
 * becomes one {@code #SBATCH} line of the script ({@link SlurmScript}), so that the script alone resubmits the job.
 */
public final class SlurmOptions {
    @Option(names = "--slurm") public boolean slurm;

    @Option(names = "--max-running", paramLabel = "T") public Integer maxRunning;

    @Option(names = "--cpus-per-task", paramLabel = "C") public Integer cpusPerTask;

    @Option(names = "--gpus-per-task", paramLabel = "G") public Integer gpusPerTask;

    @Option(names = "--cache-dir", paramLabel = "DIR") public Path cacheDir;

    @Option(names = "--partition", paramLabel = "NAME") public String partition;

    @Option(names = "--time-limit", paramLabel = "TIME") public String timeLimit;

    @Option(names = "--sbatch-option", paramLabel = "OPTION") public List<String> sbatchOptions = new ArrayList<>();

    @Option(names = "--no-wait") public boolean noWait;

    /** Refuses options that only --slurm takes given without it, and values sbatch would refuse. */
    public void validate() {
        if (!slurm) {
            List<String> given = new ArrayList<>();
            if (maxRunning != null) {
                given.add("--max-running");
            }
            if (gpusPerTask != null) {
                given.add("--gpus-per-task");
            }
            if (cacheDir != null) {
                given.add("--cache-dir");
            }
            if (partition != null) {
                given.add("--partition");
            }
            if (timeLimit != null) {
                given.add("--time-limit");
            }
            if (!sbatchOptions.isEmpty()) {
                given.add("--sbatch-option");
            }
            if (noWait) {
                given.add("--no-wait");
            }
            if (!given.isEmpty()) {
                throw new UserInputException(String.join(", ", given) + (given.size() > 1 ? " go" : " goes")
                        + " with --slurm (a job array), not --local");
            }
            atLeast("--cpus-per-task", cpusPerTask, 1);
            return;
        }
        atLeast("--max-running", maxRunning, 1);
        atLeast("--cpus-per-task", cpusPerTask, 1);
        atLeast("--gpus-per-task", gpusPerTask, 1);
        oneWord("--partition", partition);
        oneWord("--time-limit", timeLimit);
        for (String option : sbatchOptions) {
            if (!option.startsWith("-") || option.chars().anyMatch(c -> c == '\n' || c == '\r')) {
                throw new UserInputException("--sbatch-option takes one sbatch option as --name=value, got '"
                        + option.replace("\n", "\\n") + "'");
            }
        }
    }

    /** The processors each task uses. */
    int cpus() {
        return cpusPerTask != null ? cpusPerTask : 1;
    }

    private static void atLeast(String name, Integer value, int least) {
        if (value != null && value < least) {
            throw new UserInputException(name + " must be at least " + least + ", got " + value);
        }
    }

    /** A value written on an #SBATCH line: no spaces or line breaks, which would end it. */
    private static void oneWord(String name, String value) {
        if (value != null && (value.isBlank() || value.chars().anyMatch(Character::isWhitespace))) {
            throw new UserInputException(name + " takes one word, got '" + value.replace("\n", "\\n") + "'");
        }
    }
}
