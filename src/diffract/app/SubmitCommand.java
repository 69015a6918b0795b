package diffract.app;

import diffract.app.jobs.Sbatch;
import diffract.app.jobs.SlurmOptions;
import diffract.app.jobs.SlurmScript;
import diffract.app.jobs.SplitCommand;
import diffract.app.jobs.TileOptions;
import diffract.optics.MapBand;
import diffract.util.UserInputException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * {@code diffract submit --local J -- brdfmap ...} (or {@code -- render --turntable F ...}): one run of a
 * {@link SplitCommand} split into pieces ({@code --tile I/N}), computed by J worker processes on this machine, then
 * merged: it leaves the files the command names, the same bit for bit as had it run alone. {@code diffract submit --slurm ...} computes the same pieces as the tasks of a Slurm job
 * array (its script written beside the pieces), waits for the array to end and merges them the same way, or prints the
 * merge command.
 */
@Command(name = "submit", mixinStandardHelpOptions = true, abbreviateSynopsis = true)
final class SubmitCommand implements Callable<Integer> {
    @Option(names = "--local", paramLabel = "J") Integer workers;

    @Option(names = "--piece-count", paramLabel = "N") Integer pieceCount;

    @Option(names = "--keep-pieces", paramLabel = "DIR") Path keepPieces;

    @Mixin SlurmOptions slurm;

    @Parameters(paramLabel = "COMMAND OPTIONS", arity = "1..*", descriptionKey = "command-and-options")
    List<String> command;

    /** Outputs of brdfmap that merge writes, not the workers: each takes a value. */
    private static final Set<String> OUTPUTS = Set.of("-o", "--output", "--pfm", "--exr");
    private static final Pattern PIECE_TIMES = Pattern.compile("setup ([0-9.]+) s, work ([0-9.]+) s");

    @Override
    public Integer call() throws IOException, InterruptedException {
        slurm.validate();
        if (slurm.slurm == (workers != null)) {
            throw new UserInputException(slurm.slurm ? "--local and --slurm exclude each other: the pieces run either "
                    + "here or on the cluster" : "submit needs --local J (worker processes here) or --slurm (a job "
                    + "array): diffract submit --local J -- brdfmap OPTIONS");
        }
        if (workers != null && workers < 1) {
            throw new UserInputException("--local must be at least 1 worker, got " + workers);
        }
        if (slurm.slurm && pieceCount == null) {
            throw new UserInputException("--slurm needs --piece-count N, how many pieces (tasks of the array) the map "
                    + "is split into");
        }
        if (slurm.slurm && keepPieces == null) {
            throw new UserInputException("--slurm needs --keep-pieces DIR, a folder every node reads and writes: the "
                    + "pieces, the job script and the tasks' logs go there");
        }
        int count = pieceCount != null ? pieceCount : workers;
        if (count < 1) {
            throw new UserInputException("--piece-count must be at least 1, got " + count);
        }
        String name = command.get(0);
        SplitCommand single = parse(command);
        single.tiles().refuseForSubmit(name);
        single.validateSplit(count);
        SplitCommand.Result result = single.result();
        List<String> options = withoutOutputs(command.subList(1, command.size()));
        if (slurm.slurm) {
            return onSlurm(name, result, options, count, keepPieces.toAbsolutePath().normalize());
        }
        long start = System.nanoTime();
        Path dir = keepPieces != null ? keepPieces : Files.createTempDirectory("diffract-pieces-");
        try {
            List<List<String>> pieces = new ArrayList<>();
            for (int i = 0; i < count; i++) {
                List<String> piece = new ArrayList<>(List.of(name));
                piece.addAll(options);
                piece.addAll(List.of("--tile", i + "/" + count, "--pieces", dir.toString()));
                if (!result.quiet()) {
                    piece.add("--quiet"); // a worker's progress goes nowhere; a command told to be quiet already is
                }
                pieces.add(piece);
            }
            int processors = slurm.cpusPerTask != null ? slurm.cpusPerTask
                    : LocalWorkers.share(Math.min(workers, count));
            System.out.printf(Locale.ROOT, "%d pieces of %d %s on %d local workers of %d processor%s each, into %s%n",
                    count, result.items(), result.itemsName(), Math.min(workers, count), processors,
                    processors == 1 ? "" : "s", dir);
            int[] done = {0};
            LocalWorkers.Finished failed = LocalWorkers.run(pieces, single.dispatchOrder(count),
                    Math.min(workers, count), processors, f -> {
                if (f.exitCode() == 0) {
                    done[0]++;
                    System.out.println(progressLine(f, count, result, done[0], start));
                }
            });
            if (failed != null) {
                System.err.println("diffract: piece " + failed.index() + "/" + count + " failed (exit code "
                        + failed.exitCode() + "): " + Sbatch.lastLine(failed.output()));
                return failed.exitCode() == Main.EXIT_USAGE ? Main.EXIT_USAGE : 1;
            }
            int code = Main.execute(mergeArguments(result, dir, false).toArray(String[]::new));
            if (code == 0) {
                System.out.printf(Locale.ROOT, "wrote %s from %d pieces on %d workers in %.1f s%n", result.output(),
                        count, Math.min(workers, count), (System.nanoTime() - start) * 1e-9);
            }
            return code;
        } finally {
            if (keepPieces == null) {
                removePieces(dir);
            }
        }
    }

    /**
     * The pieces as a Slurm job array: its script written into the pieces' folder and submitted; then, unless told not
     * to wait, the array waited for and the pieces merged.
     */
    private int onSlurm(String name, SplitCommand.Result split, List<String> options, int count, Path dir)
            throws IOException, InterruptedException {
        long start = System.nanoTime();
        diffract.util.OutputPaths.requireWritableFolder(dir, "--keep-pieces");
        Files.createDirectories(dir);
        List<String> merge = mergeArguments(split, dir, true);
        List<String> mergeCommand = new ArrayList<>(List.of("diffract"));
        mergeCommand.addAll(merge);
        Path script = dir.resolve(SlurmScript.FILE_NAME);
        String text = SlurmScript.text(slurm, name, options, dir, count, Path.of("").toAbsolutePath(),
                LocalWorkers.javaVm(slurm.cacheDir == null), LocalWorkers.mainClass(), mergeCommand);
        diffract.util.ImageFiles.writeAtomically(script,
                out -> out.write(text.getBytes(java.nio.charset.StandardCharsets.UTF_8)));
        Sbatch.Result result = Sbatch.submit(script, !slurm.noWait, id -> System.out.printf(Locale.ROOT,
                "submitted %s as Slurm array job %s: %d pieces of %d %s%s, logs %s%n", script, id, count,
                split.items(), split.itemsName(),
                slurm.maxRunning != null ? ", at most " + slurm.maxRunning + " at once" : "",
                dir.resolve(SlurmScript.logName("I", count))));
        if (slurm.noWait) {
            System.out.println("once the array has ended: " + SlurmScript.command(mergeCommand));
            return 0;
        }
        if (result.exitCode() != 0) {
            List<String> missing = new ArrayList<>();
            for (int i = 0; i < count; i++) {
                if (!Files.isRegularFile(dir.resolve(new TileOptions.Tile(i, count).fileName(".json")))) {
                    missing.add(Integer.toString(i));
                }
            }
            if (!missing.isEmpty()) {
                throw new UserInputException("Slurm array job " + result.jobId() + " ended without piece"
                        + (missing.size() > 1 ? "s " : " ") + String.join(", ", missing) + " of " + count + " (see "
                        + dir.resolve(SlurmScript.logName(missing.get(0), count)) + "); resubmit them with sbatch "
                        + "--array=" + String.join(",", missing) + " " + script + ", then "
                        + SlurmScript.command(mergeCommand));
            }
        }
        int code = Main.execute(merge.toArray(String[]::new));
        if (code == 0) {
            System.out.printf(Locale.ROOT, "wrote %s from %d pieces of Slurm array job %s in %.1f s%n", split.output(),
                    count, result.jobId(), (System.nanoTime() - start) * 1e-9);
        }
        return code;
    }

    /**
     * The merge command that writes the outputs the command names, from the pieces in {@code dir}; with
     * {@code absolute} their paths are absolute, so that the command runs anywhere.
     */
    private static List<String> mergeArguments(SplitCommand.Result result, Path dir, boolean absolute) {
        java.util.function.Function<Path, String> path = p -> (absolute ? p.toAbsolutePath().normalize() : p)
                .toString();
        List<String> merge = new ArrayList<>(List.of("merge", path.apply(dir)));
        merge.addAll(result.mergeOutputs(path));
        if (result.quiet()) {
            merge.add("--quiet");
        }
        return merge;
    }

    /** The command as one run would read it, if it splits into pieces; its errors are submit's. */
    private static SplitCommand parse(List<String> command) {
        CommandLine.ParseResult parsed;
        try {
            parsed = Main.commandLine().setCaseInsensitiveEnumValuesAllowed(true)
                    .parseArgs(command.toArray(String[]::new));
        } catch (CommandLine.ParameterException e) {
            throw new UserInputException(command.get(0) + ": " + e.getMessage());
        }
        if (!parsed.hasSubcommand() || parsed.subcommand().isUsageHelpRequested()) {
            throw new UserInputException("submit needs a command to run: -- brdfmap OPTIONS, -- render SCENE "
                    + "--turntable F OPTIONS or -- bench OPTIONS");
        }
        if (!(parsed.subcommand().commandSpec().userObject() instanceof SplitCommand split)) {
            throw new UserInputException("submit runs brdfmap, render --turntable or bench in pieces, not "
                    + parsed.subcommand().commandSpec().name() + ": diffract submit --local J -- brdfmap OPTIONS");
        }
        return split;
    }

    /** The command's options less -o, --pfm and --exr (and their values), which merge writes. */
    static List<String> withoutOutputs(List<String> options) {
        List<String> kept = new ArrayList<>();
        for (int a = 0; a < options.size(); a++) {
            String option = options.get(a);
            String name = option.contains("=") ? option.substring(0, option.indexOf('=')) : option;
            if (OUTPUTS.contains(option)) {
                a++; // and its value
            } else if (!(OUTPUTS.contains(name) || option.startsWith("-o") && !option.startsWith("--"))) {
                kept.add(option);
            }
        }
        return kept;
    }

    /** Which piece finished, its rows, its time and how it was spent, and where the whole run stands. */
    private static String progressLine(LocalWorkers.Finished f, int count, SplitCommand.Result result, int done,
                                       long startNanos) {
        MapBand band = MapBand.of(f.index(), count, result.items());
        Matcher times = PIECE_TIMES.matcher(f.output());
        String split = "";
        if (times.find()) {
            double setup = Double.parseDouble(times.group(1));
            double work = Double.parseDouble(times.group(2));
            split = String.format(Locale.ROOT, " (start %.2f s, setup %.2f s, work %.2f s)",
                    Math.max(0, f.wallS() - setup - work), setup, work);
        }
        return String.format(Locale.ROOT, "piece %d/%d (%s %s) finished in %.2f s%s; %d of %d done, %.1f s elapsed",
                f.index(), count, result.itemsName(), band, f.wallS(), split, done, count,
                (System.nanoTime() - startNanos) * 1e-9);
    }

    /** The temporary folder and what the workers wrote in it. */
    private static void removePieces(Path dir) throws IOException {
        try (Stream<Path> files = Files.walk(dir)) {
            for (Path p : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        }
    }
}
