package diffract.app;

import diffract.util.UserInputException;
import picocli.CommandLine.Option;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * {@code submit --slurm}: the pieces as one Slurm job array, and what its tasks ask the scheduler for. Each option
 * becomes one {@code #SBATCH} line of the script ({@link SlurmScript}), so that the script alone resubmits the job.
 */
final class SlurmOptions {
    @Option(names = "--slurm",
            description = "Submit the pieces as a Slurm job array (sbatch --array=0-(N-1)) instead of running them "
                    + "here, wait for it and merge; the pieces, the job script and the tasks' logs go to "
                    + "--keep-pieces DIR, a folder every node reads and writes.")
    boolean slurm;

    @Option(names = "--max-running", paramLabel = "T",
            description = "With --slurm: at most T tasks of the array run at once (sbatch --array=...%%T; "
                    + "default: as many as the scheduler starts).")
    Integer maxRunning;

    @Option(names = "--cpus-per-task", paramLabel = "C",
            description = "The processors each piece uses: with --slurm those each task asks for (default 1); with "
                    + "--local J those each worker is told it has (default: this machine's processors shared "
                    + "among the J workers).")
    Integer cpusPerTask;

    @Option(names = "--gpus-per-task", paramLabel = "G",
            description = "With --slurm: ask for G GPUs per task (--gres=gpu:G), for partitions that give their "
                    + "nodes only so; OpenGL in a task then runs on headless EGL, the node's first GPU, with no X "
                    + "display (brdfmap's pieces themselves compute on the CPU).")
    Integer gpusPerTask;

    @Option(names = "--cache-dir", paramLabel = "DIR",
            description = "With --slurm: the disk cache the tasks share (DIFFRACT_CACHE), a folder every node reads "
                    + "and writes (default: each node's own).")
    Path cacheDir;

    @Option(names = "--partition", paramLabel = "NAME",
            description = "With --slurm: the partition (queue) the tasks run in (default: the cluster's).")
    String partition;

    @Option(names = "--time-limit", paramLabel = "TIME",
            description = "With --slurm: each task's time limit, in sbatch's form (MINUTES, HH:MM:SS, D-HH:MM).")
    String timeLimit;

    @Option(names = "--sbatch-option", paramLabel = "OPTION",
            description = "With --slurm: one more sbatch option for the script, as --name=value (repeatable; e.g. "
                    + "--sbatch-option=--account=lab --sbatch-option=--mem-per-cpu=4G).")
    List<String> sbatchOptions = new ArrayList<>();

    @Option(names = "--no-wait",
            description = "With --slurm: submit the array and print the merge command to run once it has ended, "
                    + "instead of waiting for it and merging.")
    boolean noWait;

    /** Refuses options that only --slurm takes given without it, and values sbatch would refuse. */
    void validate() {
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
