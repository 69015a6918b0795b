package diffract.app;

import diffract.app.jobs.PieceFolder;
import diffract.app.jobs.PieceManifest;
import diffract.app.jobs.TileOptions;
import diffract.bench.BenchConfig;
import diffract.bench.BenchResult;
import diffract.bench.MapError;
import diffract.bench.ResultsTable;
import diffract.jrtr.GlTestSupport;
import diffract.jrtr.contexts.GLInfo;
import diffract.util.TestCache;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A bench sweep split into runs of its configurations ({@code bench --tile I/N}) and merged writes the results one run
 * writes: the same CSV bytes from the same measured doubles, the Pareto front over all rows; a missing piece is
 * refused by name.
 */
class BenchPiecesTest {
    /** Four configurations (flss and nmm, N = 4 and 8) of one patch at one size: one Pareto front. */
    static final List<String> SWEEP = List.of("--patches", "blazed", "--variants", "flss,nmm", "--terms", "4,8",
            "--lambda-steps", "25", "--window-radii", "1", "--texture-formats", "rg32f", "--size", "24");

    /** The driver's strings, a comma in the renderer as drivers write them. */
    static final GLInfo GL = new GLInfo("4.5 (Core Profile) Mesa 22.3.6", "llvmpipe (LLVM 15.0.6, 256 bits)",
            "Mesa/X.org", "4.50", true, "EGL surfaceless");

    /**
     * Results chosen so that a merge that took the CSV's six digits, or each piece's own front, writes other bytes:
     * the first two differ only beyond six digits (exactly, each is on the front: one faster, one more accurate);
     * the last is on its own piece's front (against the third) but dominated by the first over the whole sweep. A
     * NaN error reads back too.
     */
    static List<BenchResult> measured(List<BenchConfig> configs) {
        return List.of(
                new BenchResult(configs.get(0), 1.0000004, new MapError(2.0, 5.25, 0.125, 72)),
                new BenchResult(configs.get(1), 1.0000001, new MapError(2.0000004, 5.5, 0.25, 72)),
                new BenchResult(configs.get(2), 0.5, new MapError(3.0, 7.0 / 3, Double.NaN, 70)),
                new BenchResult(configs.get(3), 2.0, new MapError(2.5, 4.0, 0.1, 72)));
    }

    static BenchCommand.Sweep sweep() {
        List<String> args = new ArrayList<>(List.of("bench"));
        args.addAll(SWEEP);
        BenchCommand bench = (BenchCommand) Main.commandLine("bench").parseArgs(args.toArray(String[]::new))
                .subcommand().commandSpec().userObject();
        return bench.sweep();
    }

    @Test
    void piecesMergeIntoTheWholeRunsCsvAndTablesBitForBit(@TempDir Path dir) throws Exception {
        BenchCommand.Sweep sweep = sweep();
        assertEquals(4, sweep.configs().size());
        List<BenchResult> results = measured(sweep.configs());
        Path pieces = dir.resolve("pieces");
        // piece 0: configurations 0..1, piece 1: 2..3 (MapBand's runs)
        PieceFolder.write(pieces, BenchCommand.pieceManifest(sweep, new TileOptions.Tile(0, 2), SWEEP,
                results.subList(0, 2), "a machine", GL), new float[0]);
        PieceFolder.write(pieces, BenchCommand.pieceManifest(sweep, new TileOptions.Tile(1, 2), SWEEP,
                results.subList(2, 4), "a machine", GL), new float[0]);
        Path out = dir.resolve("merged");
        Object[] merged = CliTest.run("merge", pieces.toString(), "-o", out.toString());
        assertEquals(0, merged[0], (String) merged[2]);
        assertTrue(((String) merged[1]).startsWith("merged 2 pieces into"), (String) merged[1]);

        String csv = Files.readString(out.resolve("results.csv"));
        assertEquals(ResultsTable.csv(results, GL), csv);
        List<String> lines = csv.lines().toList();
        int pareto = ResultsTable.COLUMNS.indexOf("pareto");
        assertEquals(List.of("true", "true", "true", "false"),
                lines.subList(1, 5).stream().map(l -> l.split(",", -1)[pareto]).toList(), csv);
        assertTrue(lines.get(3).contains(",nan,"), lines.get(3));
        assertEquals(ResultsTable.markdown(results), Files.readString(out.resolve("results.md")));
        assertEquals(ResultsTable.markdown(results, true), Files.readString(out.resolve("pareto.md")));
        assertEquals("a machine\n", Files.readString(out.resolve("machine.txt")));
        assertTrue(Files.size(out.resolve("pareto.png")) > 1000);
        assertTrue(Files.readString(out.resolve("targets.md")).startsWith("| patch |"));
    }

    @Test
    void aMissingPieceIsRefusedByName(@TempDir Path dir) throws Exception {
        BenchCommand.Sweep sweep = sweep();
        List<BenchResult> results = measured(sweep.configs());
        Path pieces = dir.resolve("pieces");
        PieceFolder.write(pieces, BenchCommand.pieceManifest(sweep, new TileOptions.Tile(0, 3), SWEEP,
                results.subList(0, 1), "a machine", GL), new float[0]);
        PieceFolder.write(pieces, BenchCommand.pieceManifest(sweep, new TileOptions.Tile(2, 3), SWEEP,
                results.subList(2, 4), "a machine", GL), new float[0]);
        Object[] merged = CliTest.run("merge", pieces.toString(), "-o", dir.resolve("merged").toString());
        assertEquals(2, merged[0]);
        assertEquals("diffract: merge: " + pieces + ": piece 1/3 is missing: run bench --tile 1/3 --pieces " + pieces
                + " with the same options\n", merged[2]);
        assertTrue(Files.notExists(dir.resolve("merged").resolve("results.csv")));
    }

    @Test
    void piecesOfAnotherRendererAreRefused(@TempDir Path dir) throws Exception {
        BenchCommand.Sweep sweep = sweep();
        List<BenchResult> results = measured(sweep.configs());
        Path pieces = dir.resolve("pieces");
        PieceFolder.write(pieces, BenchCommand.pieceManifest(sweep, new TileOptions.Tile(0, 2), SWEEP,
                results.subList(0, 2), "a machine", GL), new float[0]);
        GLInfo other = new GLInfo("4.6", "another GPU", "a vendor", "4.60", true, "EGL");
        PieceFolder.write(pieces, BenchCommand.pieceManifest(sweep, new TileOptions.Tile(1, 2), SWEEP,
                results.subList(2, 4), "another machine", other), new float[0]);
        Object[] merged = CliTest.run("merge", pieces.toString(), "-o", dir.resolve("merged").toString());
        assertEquals(2, merged[0]);
        assertTrue(((String) merged[2]).contains("bench pieces 0/2 and 1/2 ran on different OpenGL"),
                (String) merged[2]);
    }

    /** What --tile and submit refuse of a bench, before any work: one line each, exit code 2. */
    @Test
    void refusesWhatDoesNotSplit(@TempDir Path dir) {
        String pieces = dir.resolve("pieces").toString();
        String out = dir.resolve("out").toString();
        assertRefused("--tile 0/2 needs --pieces DIR, the folder its piece goes to", "--tile", "0/2");
        assertRefused("--tile writes one piece into --pieces " + pieces + "; the bench's files are written by "
                + "'diffract merge " + pieces + " -o DIR': drop -o", "--tile", "0/2", "--pieces", pieces, "-o", out);
        assertRefused("--tile 0/5: the sweep has only 4 configurations to split", "--tile", "0/5", "--pieces", pieces);
        assertRefused("bench needs -o DIR, the folder its results go to; with --tile I/N --pieces DIR it measures one "
                + "piece of the sweep instead");
        Object[] suite = CliTest.run("bench", "--gpu-suite", "--tile", "0/2", "--pieces", pieces);
        assertEquals(2, suite[0]);
        assertEquals("diffract: --tile splits the sweep's configurations; --gpu-suite and --filtering run whole: drop "
                + "--tile and --pieces\n", suite[2]);
        List<String> submit = new ArrayList<>(List.of("submit", "--local", "2", "--piece-count", "5", "--", "bench"));
        submit.addAll(SWEEP);
        submit.addAll(List.of("-o", out));
        Object[] tooMany = CliTest.run(submit.toArray(String[]::new));
        assertEquals(2, tooMany[0]);
        assertEquals("diffract: --piece-count 5: the sweep has only 4 configurations to split\n", tooMany[2]);
        assertTrue(Files.notExists(dir.resolve("pieces")) && Files.notExists(dir.resolve("out")));
    }

    private static void assertRefused(String message, String... options) {
        List<String> args = new ArrayList<>(List.of("bench"));
        args.addAll(SWEEP);
        args.addAll(List.of(options));
        Object[] result = CliTest.run(args.toArray(String[]::new));
        assertEquals(2, result[0], String.join(" ", args));
        assertEquals("diffract: " + message + "\n", result[2]);
    }

    /**
     * The sweep measured whole and by two local workers ({@code submit --local 2}): the same rows, byte for byte, but
     * for the GPU times (measured again, so they differ) and the Pareto column that follows from them; the merged times
     * are the pieces' own.
     */
    @Test
    void submitWithTwoWorkersWritesTheWholeRunsRows(@TempDir Path dir) throws Exception {
        GlTestSupport.assumeOffscreenGl();
        Path single = dir.resolve("single");
        Path split = dir.resolve("split");
        Path pieces = dir.resolve("pieces");
        try (TestCache ignored = TestCache.at(dir.resolve("cache"))) {
            List<String> whole = new ArrayList<>(List.of("bench"));
            whole.addAll(SWEEP);
            whole.addAll(List.of("-o", single.toString(), "--quiet"));
            Object[] one = CliTest.run(whole.toArray(String[]::new));
            assertEquals(0, one[0], (String) one[2]);
            List<String> submit = new ArrayList<>(List.of("submit", "--local", "2", "--keep-pieces",
                    pieces.toString(), "--", "bench"));
            submit.addAll(SWEEP);
            submit.addAll(List.of("-o", split.toString(), "--quiet"));
            Object[] two = CliTest.run(submit.toArray(String[]::new));
            assertEquals(0, two[0], two[1] + "\n" + two[2]);
        }
        int ms = ResultsTable.COLUMNS.indexOf("ms_per_frame");
        int pareto = ResultsTable.COLUMNS.indexOf("pareto");
        List<String> a = Files.readAllLines(single.resolve("results.csv"));
        List<String> b = Files.readAllLines(split.resolve("results.csv"));
        assertEquals(5, a.size(), String.join("\n", a));
        assertEquals(masked(a, ms, pareto), masked(b, ms, pareto));
        List<String> times = new ArrayList<>();
        try (Stream<Path> manifests = Files.list(pieces).filter(p -> p.toString().endsWith(".json")).sorted()) {
            for (Path m : manifests.toList()) {
                for (String row : new com.fasterxml.jackson.databind.ObjectMapper().readValue(m.toFile(),
                        PieceManifest.class).bench().rows()) {
                    times.add(row.split(" ")[0]);
                }
            }
        }
        assertEquals(4, times.size());
        for (int i = 0; i < 4; i++) {
            double piece = Double.parseDouble(times.get(i));
            double csv = Double.parseDouble(b.get(i + 1).split(",", -1)[ms]);
            assertEquals(piece, csv, 1e-5 * piece, "row " + i + ": the time its piece measured");
        }
    }

    private static List<String> masked(List<String> lines, int... columns) {
        List<String> out = new ArrayList<>();
        for (String line : lines) {
            String[] f = line.split(",", -1);
            for (int c : columns) {
                f[c] = "-";
            }
            out.add(String.join(",", f));
        }
        return out;
    }
}
