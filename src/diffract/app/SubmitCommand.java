package diffract.app;

import diffract.optics.MapBand;
import diffract.util.UserInputException;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

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
 * {@code diffract submit --local J -- brdfmap ...}: one brdfmap run split into pieces ({@code --tile I/N}), computed by
 * J worker processes on this machine, then merged: it leaves the files the brdfmap command names, the same bit for
 * bit as had it run alone.
 */
@Command(name = "submit", mixinStandardHelpOptions = true, abbreviateSynopsis = true,
        description = "Run a brdfmap command as N pieces (bands of rows) in J local worker processes, then merge "
                + "them: the same files, bit for bit, as the command alone writes. Usage: diffract submit --local J "
                + "-- brdfmap OPTIONS.")
final class SubmitCommand implements Callable<Integer> {
    @Option(names = "--local", required = true, paramLabel = "J",
            description = "How many worker processes run at once on this machine; each gets its share of the "
                    + "processors.")
    int workers;

    @Option(names = "--piece-count", paramLabel = "N",
            description = "How many pieces the map is split into (default J; more than J evens out pieces of "
                    + "unequal cost).")
    Integer pieceCount;

    @Option(names = "--keep-pieces", paramLabel = "DIR",
            description = "Leave the pieces and their manifests in DIR (default: a temporary folder, removed).")
    Path keepPieces;

    @Parameters(paramLabel = "brdfmap OPTIONS", arity = "1..*",
            description = "After --: the brdfmap command as for a single run.")
    List<String> command;

    /** Outputs of brdfmap that merge writes, not the workers: each takes a value. */
    private static final Set<String> OUTPUTS = Set.of("-o", "--output", "--pfm", "--exr");
    private static final Pattern PIECE_TIMES = Pattern.compile("setup ([0-9.]+) s, work ([0-9.]+) s");

    @Override
    public Integer call() throws IOException, InterruptedException {
        if (workers < 1) {
            throw new UserInputException("--local must be at least 1 worker, got " + workers);
        }
        int count = pieceCount != null ? pieceCount : workers;
        if (count < 1) {
            throw new UserInputException("--piece-count must be at least 1, got " + count);
        }
        if (!command.get(0).equals("brdfmap")) {
            throw new UserInputException("submit runs brdfmap: diffract submit --local J -- brdfmap OPTIONS (got '"
                    + command.get(0) + "')");
        }
        BrdfMapCommand single = parse(command);
        single.validateSplit(count);
        long start = System.nanoTime();
        Path dir = keepPieces != null ? keepPieces : Files.createTempDirectory("diffract-pieces-");
        try {
            List<String> options = withoutOutputs(command.subList(1, command.size()));
            List<List<String>> pieces = new ArrayList<>();
            for (int i = 0; i < count; i++) {
                List<String> piece = new ArrayList<>(List.of("brdfmap"));
                piece.addAll(options);
                piece.addAll(List.of("--tile", i + "/" + count, "--pieces", dir.toString(), "--quiet"));
                pieces.add(piece);
            }
            System.out.printf(Locale.ROOT, "%d pieces of %d rows on %d local workers, into %s%n", count,
                    single.picture.size, Math.min(workers, count), dir);
            int[] done = {0};
            LocalWorkers.Finished failed = LocalWorkers.run(pieces, Math.min(workers, count), f -> {
                if (f.exitCode() == 0) {
                    done[0]++;
                    System.out.println(progressLine(f, count, single.picture.size, done[0], start));
                }
            });
            if (failed != null) {
                System.err.println("diffract: piece " + failed.index() + "/" + count + " failed (exit code "
                        + failed.exitCode() + "): " + lastLine(failed.output()));
                return failed.exitCode() == Main.EXIT_USAGE ? Main.EXIT_USAGE : 1;
            }
            List<String> merge = new ArrayList<>(List.of("merge", dir.toString(), "-o", single.output.toString()));
            if (single.picture.pfm != null) {
                merge.addAll(List.of("--pfm", single.picture.pfm.toString()));
            }
            if (single.picture.exr != null) {
                merge.addAll(List.of("--exr", single.picture.exr.toString()));
            }
            if (single.quiet.quiet) {
                merge.add("--quiet");
            }
            int code = Main.execute(merge.toArray(String[]::new));
            if (code == 0) {
                System.out.printf(Locale.ROOT, "wrote %s from %d pieces on %d workers in %.1f s%n", single.output,
                        count, Math.min(workers, count), (System.nanoTime() - start) * 1e-9);
            }
            return code;
        } finally {
            if (keepPieces == null) {
                removePieces(dir);
            }
        }
    }

    /** The brdfmap command as one run would read it; its errors are submit's. */
    private static BrdfMapCommand parse(List<String> command) {
        try {
            CommandLine.ParseResult parsed = new CommandLine(new Main()).setCaseInsensitiveEnumValuesAllowed(true)
                    .parseArgs(command.toArray(String[]::new));
            if (!parsed.hasSubcommand() || parsed.subcommand().isUsageHelpRequested()) {
                throw new UserInputException("submit needs a brdfmap command to run: -- brdfmap OPTIONS");
            }
            return (BrdfMapCommand) parsed.subcommand().commandSpec().userObject();
        } catch (CommandLine.ParameterException e) {
            throw new UserInputException("brdfmap: " + e.getMessage());
        }
    }

    /** The brdfmap options less -o, --pfm and --exr (and their values), which merge writes. */
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
    private static String progressLine(LocalWorkers.Finished f, int count, int sizePx, int done, long startNanos) {
        MapBand band = MapBand.of(f.index(), count, sizePx);
        Matcher times = PIECE_TIMES.matcher(f.output());
        String split = "";
        if (times.find()) {
            double setup = Double.parseDouble(times.group(1));
            double work = Double.parseDouble(times.group(2));
            split = String.format(Locale.ROOT, " (start %.2f s, setup %.2f s, work %.2f s)",
                    Math.max(0, f.wallS() - setup - work), setup, work);
        }
        return String.format(Locale.ROOT, "piece %d/%d (rows %s) finished in %.2f s%s; %d of %d done, %.1f s elapsed",
                f.index(), count, band, f.wallS(), split, done, count, (System.nanoTime() - startNanos) * 1e-9);
    }

    private static String lastLine(String output) {
        String[] lines = output.strip().split("\n");
        return lines.length == 0 || lines[lines.length - 1].isBlank() ? "(no output)" : lines[lines.length - 1].strip();
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
