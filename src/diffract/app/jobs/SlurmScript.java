package diffract.app.jobs;

import diffract.jrtr.contexts.HeadlessGL;
import diffract.util.DiskCache;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;

/**
 * The sbatch script of {@code submit --slurm}: a job array whose task I runs {@code brdfmap ... --tile I/N --pieces
 * DIR} with this program's Java, class path and heap, on a node that the scheduler chose. Everything the scheduler is
 * asked is an {@code #SBATCH} line, so that {@code sbatch DIR/job.sbatch} resubmits the job as it was (or
 * {@code sbatch --array=3,5 DIR/job.sbatch} the pieces that failed).
 */
public final class SlurmScript {
    /** The script's name in the pieces' folder. */
    public static final String FILE_NAME = "job.sbatch";

    private SlurmScript() {
    }

    /** The log of piece I of N, beside its manifest (Slurm's %a is the task's index). */
    public static String logName(String index, int count) {
        return "piece-" + index + "-of-" + count + ".log";
    }

    /**
     * The script's text.
     *
     * @param commandName the command the pieces run: brdfmap, render with --turntable, or bench
     * @param options the command's options of one piece, less --tile, --pieces and the outputs that merge writes
     * @param pieces  the pieces' folder, absolute: the nodes write there
     * @param count   how many pieces (tasks)
     * @param workDir the folder the tasks run in, where the options' relative paths start
     * @param java    java and its options (no processor count, no class path)
     * @param main    the class path and entry point
     * @param merge   the merge command that ends the run, for the header
     */
    public static String text(SlurmOptions slurm, String commandName, List<String> options, Path pieces, int count,
            Path workDir,
            List<String> java, List<String> main, List<String> merge) {
        StringBuilder s = new StringBuilder();
        s.append("#!/bin/bash\n");
        s.append("# Written by 'diffract submit --slurm': task I of this array computes piece I of ").append(count)
                .append(switch (commandName) {
                    case "render" -> " of a turntable's frames\n";
                    case "bench" -> " of a bench sweep's configurations\n";
                    default -> " of a BRDF map\n";
                });
        s.append("# into this folder. Resubmit with: sbatch ").append(quote(pieces.resolve(FILE_NAME).toString()))
                .append(" (pieces that failed: sbatch --array=I,J ...);\n");
        s.append("# once every piece is there: ").append(command(merge)).append('\n');
        sbatch(s, "--job-name=diffract-" + commandName);
        sbatch(s, "--array=0-" + (count - 1) + (slurm.maxRunning != null ? "%" + slurm.maxRunning : ""));
        sbatch(s, "--ntasks=1");
        sbatch(s, "--cpus-per-task=" + slurm.cpus());
        if (slurm.gpusPerTask != null) {
            sbatch(s, "--gres=gpu:" + slurm.gpusPerTask);
        }
        if (slurm.partition != null) {
            sbatch(s, "--partition=" + slurm.partition);
        }
        if (slurm.timeLimit != null) {
            sbatch(s, "--time=" + slurm.timeLimit);
        }
        sbatch(s, "--chdir=" + sbatchPath(workDir));
        sbatch(s, "--output=" + sbatchPath(pieces.resolve(logName("%a", count))));
        for (String option : slurm.sbatchOptions) {
            sbatch(s, option);
        }
        s.append("set -euo pipefail\n");
        if (slurm.cacheDir != null) {
            s.append("# the disk cache every task shares: what one computed, the others read\n");
            s.append("export ").append(DiskCache.ROOT_VARIABLE).append('=')
                    .append(quote(slurm.cacheDir.toAbsolutePath().normalize().toString())).append('\n');
        }
        if (slurm.gpusPerTask != null) {
            s.append("# a GPU node: OpenGL on headless EGL (the first device the node shows this task), no X display\n");
            s.append("unset DISPLAY\n");
            s.append("export ").append(HeadlessGL.PLATFORM_VARIABLE).append("=egl\n");
        }
        List<String> tile = new ArrayList<>(List.of(commandName));
        tile.addAll(options);
        List<String> vm = new ArrayList<>(java);
        if (vm.stream().noneMatch(o -> o.startsWith("-Djava.awt.headless="))) {
            vm.add("-Djava.awt.headless=true"); // a node has no display
        }
        s.append("exec ").append(command(vm))
                .append(" \"-XX:ActiveProcessorCount=${SLURM_CPUS_PER_TASK:-").append(slurm.cpus()).append("}\" ")
                .append(command(main)).append(' ').append(command(tile))
                .append(" --tile \"${SLURM_ARRAY_TASK_ID}/").append(count).append("\" --pieces ")
                .append(quote(pieces.toString())).append('\n');
        return s.toString();
    }

    private static void sbatch(StringBuilder s, String option) {
        s.append("#SBATCH ").append(option).append('\n');
    }

    /** A path on an #SBATCH line: sbatch splits those at blanks, except within double quotes, which it drops. */
    private static String sbatchPath(Path path) {
        String text = path.toString();
        return text.chars().anyMatch(Character::isWhitespace) ? "\"" + text + "\"" : text;
    }

    /** A command line as the shell reads it back word for word. */
    public static String command(List<String> words) {
        return words.stream().map(SlurmScript::quote).collect(Collectors.joining(" "));
    }

    /** One word for the shell: as it is when it holds nothing the shell would read, else in single quotes. */
    public static String quote(String word) {
        if (!word.isEmpty() && word.matches("[A-Za-z0-9_@%+=:,./-]+")) {
            return word;
        }
        return "'" + word.replace("'", "'\\''") + "'";
    }
}
