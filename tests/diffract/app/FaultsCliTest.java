package diffract.app;

import diffract.optics.patches.SyntheticPatches;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.io.GsfWriter;
import diffract.precompute.TermStore;
import diffract.util.ImageFiles;
import diffract.util.TestCache;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.io.RandomAccessFile;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletionException;
import java.util.concurrent.CyclicBarrier;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Faults and long work through the real command line: damaged term folders and cache entries repair themselves,
 * stale temporary files go, concurrent precomputes end consistent, an unwritable cache computes in memory, outputs
 * and memory are checked before any work, no failure shows a stack trace, a black map says why, and --quiet.
 */
class FaultsCliTest {
    @TempDir
    static Path shared;
    static Path grating;

    @TempDir
    Path dir;

    @BeforeAll
    static void writeGrating() throws IOException {
        // 0.05 um pixels: no aliasing warning beside what a test expects; 8 rows: 0.4 um, wider than the shortest
        // wavelength, as a readable scan must be
        grating = shared.resolve("blazed.gsf");
        GsfWriter.write(grating, SyntheticPatches.blazed(2.5, 0.13, 50, 4, 8));
    }

    private TestCache cache;

    @BeforeEach
    void privateCache() {
        cache = TestCache.at(dir.resolve("cache"));
    }

    @AfterEach
    void backToTheBuildsCache() {
        cache.close();
    }

    private static Object[] run(String... args) {
        return CliTest.run(args);
    }

    private static String err(Object[] result) {
        return (String) result[2];
    }

    private static String out(Object[] result) {
        return (String) result[1];
    }

    /** One line on stderr, exit code 2, no trace. */
    private static void assertOneLineRefusal(Object[] result, String expected) {
        assertEquals(2, result[0], err(result));
        String e = err(result).strip();
        assertEquals(1, e.lines().count(), e);
        assertTrue(e.startsWith("diffract: "), e);
        assertTrue(e.contains(expected), e);
        assertFalse(e.contains("Exception") || e.contains("\tat "), e);
    }

    private static void flipBytes(Path file, long at) throws IOException {
        try (RandomAccessFile raf = new RandomAccessFile(file.toFile(), "rw")) {
            byte[] bytes = new byte[4];
            raf.seek(at);
            raf.readFully(bytes);
            for (int i = 0; i < 4; i++) {
                bytes[i] = (byte) ~bytes[i];
            }
            raf.seek(at);
            raf.write(bytes);
        }
    }

    private static void assertSameTerms(TaylorTerms expected, TaylorTerms actual) {
        assertEquals(expected.termCount(), actual.termCount());
        for (int n = 0; n < expected.termCount(); n++) {
            assertArrayEquals(expected.termData(n), actual.termData(n), "term " + n);
        }
    }

    private static List<String> names(Path folder) throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return files.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void aDamagedFolderSaysHowToRepairItAndARerunOfPrecomputeRepairsIt() throws IOException {
        Path terms = dir.resolve("T");
        String[] precompute = {"precompute", "--patch", grating.toString(), "--terms", "10", "-o", terms.toString()};
        assertEquals(0, run(precompute)[0]);
        TaylorTerms good = TermStore.read(terms);
        flipBytes(terms.resolve(TermStore.DATA_FILE), 100);
        String[] brdfmap = {"brdfmap", "--patch", grating.toString(), "--theta-i", "30", "--variant", "flss",
                "--terms", "10", "--terms-dir", terms.toString(), "--size", "8", "-o", dir.resolve("m.png").toString()};
        Object[] refused = run(brdfmap);
        assertOneLineRefusal(refused, "terms.f32 fails its checksum");
        assertTrue(err(refused).contains("patch blazed.gsf, N = 10") && err(refused).contains("-o " + terms),
                "names the precompute that repairs it: " + err(refused));

        Object[] repaired = run(precompute);
        assertEquals(0, repaired[0], err(repaired));
        assertTrue(out(repaired).startsWith("computed 11 terms"), "recomputed, not reused: " + out(repaired));
        assertTrue(err(repaired).contains("terms.f32 fails its checksum (corrupt or modified): recomputing"),
                err(repaired));
        assertSameTerms(good, TermStore.read(terms));
        assertEquals(0, run(brdfmap)[0]);
        assertTrue(out(run(precompute)).startsWith("reused 11 terms"), "a sound folder is reused");
    }

    /**
     * A writer killed between its renames (new data beside the old sidecar, or data without a sidecar) and its
     * temporary files: the next precompute recomputes and removes the leftovers.
     */
    @Test
    void whatAKilledWriterLeavesIsRepairedAndItsTemporaryFilesRemoved() throws IOException {
        Path terms = dir.resolve("T");
        String[] precompute = {"precompute", "--patch", grating.toString(), "--terms", "6", "-o", terms.toString()};
        assertEquals(0, run(precompute)[0]);
        TaylorTerms good = TermStore.read(terms);
        flipBytes(terms.resolve(TermStore.DATA_FILE), 8); // other data of the same size beside the old sidecar
        Files.writeString(terms.resolve("terms.f32.tmp-4242-1"), "half a file");
        Files.writeString(terms.resolve("terms.json.tmp-4242-2"), "{");

        Object[] repaired = run(precompute);
        assertEquals(0, repaired[0], err(repaired));
        assertTrue(out(repaired).startsWith("computed 7 terms"), out(repaired));
        assertTrue(err(repaired).contains("removed 2 temporary files"), err(repaired));
        assertEquals(List.of(".lock", "terms.f32", "terms.json"), names(terms));
        assertSameTerms(good, TermStore.read(terms));

        Files.delete(terms.resolve(TermStore.SIDECAR_FILE)); // killed before the sidecar's rename
        Object[] again = run(precompute);
        assertTrue(out(again).startsWith("computed 7 terms"), out(again));
        assertTrue(err(again).contains("has no terms.json beside it (an interrupted write): recomputing"), err(again));
        assertSameTerms(good, TermStore.read(terms));
    }

    /** The cache entry of brdfmap: invalid JSON, no data key, corrupt data; each is recomputed with a notice. */
    @Test
    void damagedCacheEntriesAreRecomputedWithANotice() throws IOException {
        Path pfm = dir.resolve("m.pfm");
        String[] brdfmap = {"brdfmap", "--patch", grating.toString(), "--theta-i", "30", "--variant", "flss",
                "--terms", "8", "--size", "12", "--coherence-length", "2", "--exposure", "auto", "-o",
                dir.resolve("m.png").toString(), "--pfm", pfm.toString()};
        assertEquals(0, run(brdfmap)[0]);
        float[] expected = ImageFiles.readPfm(pfm, new int[3]);
        assertTrue(max(expected) > 1e-3, "a lit map, so that the same map means the same terms");
        Path entry;
        try (Stream<Path> entries = Files.list(dir.resolve("cache").resolve("terms"))) {
            entry = entries.findFirst().orElseThrow();
        }
        Path sidecar = entry.resolve(TermStore.SIDECAR_FILE);
        String goodSidecar = Files.readString(sidecar);

        List<String[]> damages = List.of(
                new String[] {"invalid JSON", "is not readable JSON"},
                new String[] {"no data key", "is incomplete: no 'data'"},
                new String[] {"corrupt data", "terms.f32 fails its checksum"});
        for (String[] damage : damages) {
            switch (damage[0]) {
                case "invalid JSON" -> Files.writeString(sidecar, goodSidecar.substring(0, goodSidecar.length() / 2));
                case "no data key" -> {
                    com.fasterxml.jackson.databind.ObjectMapper json = new com.fasterxml.jackson.databind.ObjectMapper();
                    com.fasterxml.jackson.databind.node.ObjectNode tree =
                            (com.fasterxml.jackson.databind.node.ObjectNode) json.readTree(goodSidecar);
                    tree.remove("data");
                    Files.writeString(sidecar, json.writeValueAsString(tree));
                }
                default -> flipBytes(entry.resolve(TermStore.DATA_FILE), 16);
            }
            Object[] result = run(brdfmap);
            assertEquals(0, result[0], damage[0] + ": " + err(result));
            assertTrue(err(result).contains(damage[1]) && err(result).contains(": recomputing"),
                    damage[0] + ": " + err(result));
            assertTrue(err(result).contains("cached Taylor terms in " + entry), damage[0] + ": " + err(result));
            assertArrayEquals(expected, ImageFiles.readPfm(pfm, new int[3]), damage[0] + ": the same map");
            TermStore.read(entry); // sound again
        }
    }

    /** A cache that cannot be written: the terms are computed in memory, and the command says so. */
    @Test
    void anUnwritableCacheComputesInMemory() throws IOException {
        Path notAFolder = dir.resolve("file");
        Files.writeString(notAFolder, "a file where the cache folder would be");
        System.setProperty(diffract.util.DiskCache.ROOT_PROPERTY, notAFolder.resolve("cache").toString());
        Path png = dir.resolve("m.png");
        Object[] result = run("brdfmap", "--patch", grating.toString(), "--theta-i", "30", "--variant", "flss",
                "--terms", "6", "--size", "12", "-o", png.toString());
        assertEquals(0, result[0], err(result));
        assertTrue(err(result).contains("is not writable") && err(result).contains("computing the terms in memory"),
                err(result));
        assertEquals(12, ImageIO.read(png.toFile()).getWidth());
    }

    /**
     * {@code --no-cache}: nothing is read or written. The first run makes no cache folder; after a run that fills the
     * cache, another with the flag leaves every file as it was (not even its time of use changes), and does not
     * repair a damaged entry, which it would have had to read to notice.
     */
    @Test
    void noCacheNeitherReadsNorWritesTheCache() throws IOException {
        Path cacheDir = dir.resolve("cache");
        List<String> brdfmap = List.of("brdfmap", "--patch", grating.toString(), "--theta-i", "30", "--variant",
                "flss", "--terms", "6", "--size", "12", "-o", dir.resolve("m.png").toString());
        List<String> noCache = new ArrayList<>(brdfmap);
        noCache.add("--no-cache");
        Object[] first = run(noCache.toArray(new String[0]));
        assertEquals(0, first[0], err(first));
        assertFalse(Files.exists(cacheDir), "no cache folder: " + err(first));

        assertEquals(0, run(brdfmap.toArray(new String[0]))[0]);
        Path entry;
        try (Stream<Path> entries = Files.list(cacheDir.resolve("terms"))) {
            entry = entries.findFirst().orElseThrow();
        }
        flipBytes(entry.resolve(TermStore.DATA_FILE), 16);
        Files.setLastModifiedTime(entry, java.nio.file.attribute.FileTime.fromMillis(1_000_000_000_000L));
        List<String> before = snapshot(cacheDir);
        Object[] again = run(noCache.toArray(new String[0]));
        assertEquals(0, again[0], err(again));
        assertFalse(err(again).contains("recomputing"), "the damaged entry was not read: " + err(again));
        assertEquals(before, snapshot(cacheDir), "the cache folder is untouched");

        Object[] repaired = run(brdfmap.toArray(new String[0])); // without the flag the cache is used again
        assertTrue(err(repaired).contains("fails its checksum") && err(repaired).contains(": recomputing"),
                err(repaired));
    }

    /** {@code --no-cache} on a GPU command: the baked table is baked and not stored. */
    @Test
    void noCacheStoresNoBakedTable() {
        diffract.jrtr.GlTestSupport.assumeOffscreenGl();
        Path cacheDir = dir.resolve("cache");
        Object[] result = run("brdfmap", "--patch", grating.toString(), "--theta-i", "30", "--engine", "gpu",
                "--variant", "baked", "--baked-samples", "9,2", "--terms", "20", "--size", "12", "--no-cache", "-o",
                dir.resolve("b.png").toString());
        assertEquals(0, result[0], err(result));
        assertFalse(Files.exists(cacheDir), "no cache folder: " + err(result));
        Object[] cached = run("brdfmap", "--patch", grating.toString(), "--theta-i", "30", "--engine", "gpu",
                "--variant", "baked", "--baked-samples", "9,2", "--terms", "20", "--size", "12", "-o",
                dir.resolve("b.png").toString());
        assertEquals(0, cached[0], err(cached));
        assertTrue(Files.isDirectory(cacheDir.resolve("baked-tables")), err(cached));
        assertTrue(diffract.util.DiskCache.diskInUse(), "the flag applies to its command only");
    }

    /** Every file under {@code dir} with its size, time of modification and content hash. */
    private static List<String> snapshot(Path dir) throws IOException {
        try (Stream<Path> files = Files.walk(dir)) {
            List<String> lines = new ArrayList<>();
            for (Path p : files.sorted().toList()) {
                lines.add(dir.relativize(p) + " " + Files.getLastModifiedTime(p).toMillis() + " "
                        + (Files.isRegularFile(p) ? Files.size(p) + " "
                        + diffract.util.DiskCache.sha256Hex(Files.readAllBytes(p)) : "folder"));
            }
            return lines;
        }
    }

    /** Two precomputes into one folder at once, as threads of this process: one computes, the other reuses. */
    @Test
    void concurrentPrecomputesInOneProcessEndConsistent() throws Exception {
        Path terms = dir.resolve("T");
        Path bigger = dir.resolve("bigger.gsf");
        GsfWriter.write(bigger, SyntheticPatches.blazed(2.5, 0.13, 16, 16, 64)); // long enough to overlap
        String[] args = {"precompute", "--patch", bigger.toString(), "--terms", "20", "-o", terms.toString()};
        PrintStream out = System.out;
        PrintStream err = System.err;
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        ExecutorService pool = Executors.newFixedThreadPool(2);
        try {
            System.setOut(new PrintStream(o, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(e, true, StandardCharsets.UTF_8));
            CyclicBarrier start = new CyclicBarrier(2);
            List<Future<Integer>> codes = new ArrayList<>();
            for (int t = 0; t < 2; t++) {
                codes.add(pool.submit(() -> {
                    start.await();
                    return Main.execute(args);
                }));
            }
            for (Future<Integer> code : codes) {
                assertEquals(0, code.get());
            }
        } finally {
            pool.shutdown();
            System.setOut(out);
            System.setErr(err);
        }
        String stdout = o.toString(StandardCharsets.UTF_8);
        assertEquals(1, stdout.lines().filter(l -> l.startsWith("computed 21 terms")).count(), stdout);
        assertEquals(1, stdout.lines().filter(l -> l.startsWith("reused 21 terms")).count(), stdout);
        assertFalse(e.toString(StandardCharsets.UTF_8).contains("recomputing"), "nobody saw a half-written folder");
        assertEquals(21, TermStore.read(terms).termCount());
        assertEquals(List.of(".lock", "terms.f32", "terms.json"), names(terms));
    }

    /** Two precompute processes into one folder: the OS file lock makes one wait, and the folder ends sound. */
    @Test
    void concurrentPrecomputeProcessesEndConsistent() throws Exception {
        Path terms = dir.resolve("T");
        Path bigger = dir.resolve("bigger.gsf");
        GsfWriter.write(bigger, SyntheticPatches.blazed(2.5, 0.13, 16, 16, 64));
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<Process> processes = new ArrayList<>();
        for (int t = 0; t < 2; t++) {
            processes.add(new ProcessBuilder(java, "-Xmx512m", "-cp", System.getProperty("java.class.path"),
                    "diffract.app.Main", "precompute", "--quiet", "--patch", bigger.toString(), "--terms", "20", "-o",
                    terms.toString()).redirectErrorStream(true).start());
        }
        List<String> lines = new ArrayList<>();
        for (Process p : processes) {
            String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertEquals(0, p.waitFor(), output);
            lines.addAll(output.lines().toList());
        }
        assertEquals(1, lines.stream().filter(l -> l.startsWith("computed 21 terms")).count(), lines.toString());
        assertEquals(1, lines.stream().filter(l -> l.startsWith("reused 21 terms")).count(), lines.toString());
        assertEquals(21, TermStore.read(terms).termCount());
    }

    /**
     * Outputs are checked before the work: the patch named here does not exist, so a refusal that names the output
     * shows that the check came first.
     */
    @Test
    void outputsThatCannotBeWrittenAreRefusedBeforeAnyWork() throws IOException {
        String missingPatch = dir.resolve("no-such-patch.gsf").toString();
        Path file = dir.resolve("a-file");
        Files.writeString(file, "x");
        assertOneLineRefusal(run("brdfmap", "--patch", missingPatch, "--theta-i", "30", "-o", dir.toString()),
                "-o " + dir + " is a folder; name the file to write, e.g. " + dir.resolve("map.png"));
        assertOneLineRefusal(run("brdfmap", "--patch", missingPatch, "--theta-i", "30", "-o",
                dir.resolve("m.png").toString(), "--pfm", file.resolve("m.pfm").toString()),
                "cannot write --pfm " + file.resolve("m.pfm") + ": " + file + " is a file, not a folder");
        assertOneLineRefusal(run("precompute", "--patch", missingPatch, "--terms", "3", "-o", file.toString()),
                "-o " + file + " is a file, not a folder");
        assertOneLineRefusal(run("precompute", "--patch", missingPatch, "--terms", "3", "-o",
                file.resolve("T").toString()), "is a file, not a folder");
        assertOneLineRefusal(run("patch", "blazed", "-o", file.resolve("p.gsf").toString()),
                "is a file, not a folder");
        Path folderPng = Files.createDirectories(dir.resolve("sub.png"));
        assertOneLineRefusal(run("render", "--synthetic", "blazed", "--size", "16x16", "-o", folderPng.toString()),
                "-o " + folderPng + " is a folder");
        assertOneLineRefusal(run("convert-terms", "--from", dir.toString(), "--to", file.toString()),
                "--to " + file + " is a file, not a folder");
        assertFalse(Files.exists(dir.resolve("cache")), "no work was done");
    }

    /**
     * A 2048 x 2048 patch 0.3 um high, whose reference map keeps 5 phase centres of 16 double
     * complex transforms (5.4 GB): refused at once with the estimate and the ways out, under the tests' 4 GB heap.
     */
    @Test
    void aReferenceMapTooLargeForTheHeapIsRefusedWithTheEstimate() throws IOException {
        int n = 2048;
        BufferedImage image = new BufferedImage(n, n, BufferedImage.TYPE_BYTE_GRAY);
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                image.getRaster().setSample(c, r, 0, 255 * (c % 50) / 50);
            }
        }
        Path png = dir.resolve("saw2048.png");
        ImageIO.write(image, "png", png.toFile());
        Object[] result = run("brdfmap", "--patch", png.toString(), "--max-height", "0.3", "--pixel-size", "0.05",
                "--theta-i", "30", "--size", "64", "-o", dir.resolve("m.png").toString());
        assertOneLineRefusal(result, "the reference map of a 2048x2048 patch needs about");
        assertTrue(err(result).contains("exact spectrum: 5 phase centres x 16 transforms of 2048x2048 5.5 GB"),
                err(result));
        assertTrue(err(result).contains("--variant flss (its 31 terms take 1.0 GB)"), err(result));
        assertTrue(err(result).contains("-Xmx") || err(result).contains("more than this machine's"), err(result));
        assertFalse(Files.exists(dir.resolve("m.png")));

        Object[] huge = run("patch", "blazed", "--periods", "100000", "--rows", "100000", "-o",
                dir.resolve("huge.gsf").toString());
        assertOneLineRefusal(huge, "a 2500000 x 100000 grating needs about 5.0 TB of memory");
    }

    /** OutOfMemoryError, also from inside a worker thread, ends in one line and exit code 2: no trace. */
    @Test
    void outOfMemoryIsOneLine() {
        PrintStream err = System.err;
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        try {
            System.setErr(new PrintStream(e, true, StandardCharsets.UTF_8));
            assertEquals(2, Main.failure(new OutOfMemoryError("Java heap space"), false));
            assertEquals(2, Main.failure(new CompletionException(new OutOfMemoryError("Java heap space")), false));
            assertEquals(2, Main.failure(new java.io.UncheckedIOException(
                    new java.nio.file.AccessDeniedException("/x/y")), false));
        } finally {
            System.setErr(err);
        }
        List<String> lines = e.toString(StandardCharsets.UTF_8).lines().toList();
        assertEquals(3, lines.size(), lines.toString());
        assertTrue(lines.get(0).startsWith("diffract: out of memory:") && lines.get(0).contains("-Xmx"), lines.get(0));
        assertEquals(lines.get(0), lines.get(1));
        assertEquals("diffract: permission denied: /x/y", lines.get(2));
    }

    /**
     * A map whose narrow orders fall between its pixels (a 80 um patch: sigma_f = 0.78 texels, pixels 4.3 texels
     * apart) comes out black with the thesis' 3 x 3 window: the warning says so and names --window-radius auto,
     * which lights it. At exposure 1 the lit map is still dark: that notice names --exposure auto.
     */
    @Test
    void aBlackMapSaysSoAndNamesTheOptionThatShowsIt() throws IOException {
        int n = 400;
        BufferedImage image = new BufferedImage(n, n, BufferedImage.TYPE_BYTE_GRAY);
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                image.getRaster().setSample(c, r, 0, 255 * (c % 20) / 20);
            }
        }
        Path png = dir.resolve("saw400.png");
        ImageIO.write(image, "png", png.toFile());
        Path pfm = dir.resolve("m.pfm");
        List<String> common = List.of("brdfmap", "--patch", png.toString(), "--max-height", "0.3", "--pixel-size",
                "0.2", "--theta-i", "30", "--variant", "flss", "--terms", "10", "--size", "64", "-o",
                dir.resolve("m.png").toString(), "--pfm", pfm.toString());
        Object[] black = run(common.toArray(String[]::new));
        assertEquals(0, black[0], err(black));
        assertTrue(err(black).contains("warning: the map is black: no pixel holds any light"), err(black));
        assertTrue(err(black).contains("--window-radius auto (7 x 7 here)"), err(black));
        assertTrue(max(ImageFiles.readPfm(pfm, new int[3])) < 1e-20, "black indeed");

        List<String> auto = new ArrayList<>(common);
        auto.addAll(List.of("--window-radius", "auto"));
        Object[] lit = run(auto.toArray(String[]::new));
        assertEquals(0, lit[0], err(lit));
        assertTrue(max(ImageFiles.readPfm(pfm, new int[3])) > 1e-6, "the suggested option lights the map");
        assertFalse(err(lit).contains("no pixel holds any light"), err(lit));
        assertTrue(err(lit).contains("the map is black at --exposure 1") && err(lit).contains("--exposure auto"),
                err(lit));

        auto.addAll(List.of("--exposure", "auto"));
        Object[] shown = run(auto.toArray(String[]::new));
        assertEquals(0, shown[0], err(shown));
        assertFalse(err(shown).contains("black") || err(shown).contains("dim"), err(shown));
    }

    private static double max(float[] values) {
        double max = 0;
        for (float v : values) {
            max = Math.max(max, v);
        }
        return max;
    }

    /** --quiet: no notes, no progress; the result line stays. Without it the notes are there. */
    @Test
    void quietKeepsOnlyTheResult() throws IOException {
        Path fine = grating; // no aliasing warning, which --quiet would keep
        String[] args = {"precompute", "--patch", fine.toString(), "--terms", "5", "-o",
                dir.resolve("T").toString()};
        Object[] loud = run(args);
        assertTrue(err(loud).contains("Taylor order N = 5"), err(loud));
        String[] quiet = java.util.Arrays.copyOf(args, args.length + 1);
        quiet[args.length] = "--quiet";
        Object[] result = run(quiet);
        assertEquals(0, result[0]);
        assertTrue(out(result).startsWith("reused 6 terms"), out(result));
        assertEquals("", err(result));
        // a short coherence length widens the orders: the map is lit (no black-map warning)
        String[] map = {"brdfmap", "--patch", fine.toString(), "--theta-i", "30", "--variant", "flss",
                "--terms", "5", "--size", "16", "--coherence-length", "2", "--exposure", "auto", "-o",
                dir.resolve("m.png").toString()};
        assertTrue(err(run(map)).contains("flss, 200x8 patch"), "the notes a map prints without --quiet");
        String[] quietMap = java.util.Arrays.copyOf(map, map.length + 1);
        quietMap[map.length] = "-q";
        Object[] mapResult = run(quietMap);
        assertEquals(0, mapResult[0]);
        assertTrue(out(mapResult).startsWith("wrote "), out(mapResult));
        // warnings stay (here the scalar model's expected distance from Maxwell's equations); the notes go
        assertTrue(err(mapResult).lines().allMatch(l -> l.startsWith("warning: ")), err(mapResult));
        for (String command : new String[] {"demo", "precompute", "brdfmap", "compare", "convert-terms", "patch",
                "channels", "view", "render", "bench"}) {
            assertTrue(out(run(command, "--help")).contains("--quiet"), command + " has --quiet");
        }
    }

    /**
     * Progress only for work that lasts: a map's progress lines are never more than the rule allows for the time
     * it took (none in the first 2 s, then one per 5 s, plus the line that ends it), whatever the machine's speed.
     */
    @Test
    void shortWorkPrintsNoPercentageLines() {
        long start = System.nanoTime();
        Object[] result = run("brdfmap", "--patch", grating.toString(), "--theta-i", "30", "--size", "32",
                "--exposure", "auto", "-o", dir.resolve("m.png").toString());
        double seconds = (System.nanoTime() - start) * 1e-9;
        assertEquals(0, result[0], err(result));
        long progressLines = err(result).lines().filter(l -> l.startsWith("BRDF map 32x32:")).count();
        long allowed = seconds < 2 ? 0 : 2 + (long) ((seconds - 2) / 5);
        assertTrue(progressLines <= allowed, progressLines + " progress lines in " + seconds + " s: " + err(result));
    }
    /** The smaller faults: each message names the file, the value or the line, in the user's words. */
    @Test
    void messagesNameTheValueTheLineAndTheFileWithoutInternals() throws IOException {
        Path png = dir.resolve("map.png");
        Path pfm = dir.resolve("map.pfm");
        assertEquals(0, run("brdfmap", "--patch", grating.toString(), "--theta-i", "30", "--variant", "flss",
                "--terms", "4", "--size", "8", "-o", png.toString(), "--pfm", pfm.toString())[0]);
        assertOneLineRefusal(run("compare", png.toString(), pfm.toString()),
                png + ": not a PFM file: it does not start with PF or Pf (it is a PNG); compare reads the float maps"
                        + " brdfmap writes with --pfm MAP.pfm");
        assertOneLineRefusal(run("patch", "blazed", "--period", "0", "-o", dir.resolve("p.gsf").toString()),
                "--period must be a positive number of micrometres, got 0.0");
        assertOneLineRefusal(run("patch", "sinusoid", "--samples-per-period", "1", "-o",
                dir.resolve("p.gsf").toString()), "--samples-per-period must be at least 2, got 1");

        // 100 arrays nested on lines 3, 4, ...: the 64th array (depth 65 under the root object) is on line 66
        Path deep = dir.resolve("deep.json");
        Files.writeString(deep, "{\n\"camera\":\n" + "[\n".repeat(100) + "]".repeat(100) + "\n}\n");
        assertOneLineRefusal(run("render", deep.toString(), "-o", dir.resolve("r.png").toString()),
                "deep.json:66: (json): objects and arrays nest more than 64 levels deep here");
        assertFalse(err(run("render", deep.toString(), "-o", dir.resolve("r.png").toString()))
                .contains("StreamReadConstraints"));

        Object[] none = run();
        assertEquals(2, none[0]);
        assertEquals(List.of("diffract: missing command: one of demo, precompute, brdfmap, compare, orders, validity,"
                + " convert-terms, patch, channels, view, render, measure, bench, export, merge, submit; try 'diffract"
                + " --help'"),
                err(none).lines().toList());
    }

    /**
     * The aliasing note follows the light: the default grating (0.1 um pixels) aliases for no wavelength at
     * theta_i = 30 (|u| <= 1.5, lambda < 300 nm), and for 380-393 nm at 75 degrees (|u| <= 1.966); precompute knows
     * no light and notes nothing. One line for both axes of a square pixel.
     */
    @Test
    void theAliasingNoteFollowsTheLightAndSparesTheDefaultGrating() {
        Path patch = dir.resolve("default.gsf");
        assertEquals(0, run("patch", "blazed", "-o", patch.toString())[0]);
        Object[] precompute = run("precompute", "--patch", patch.toString(), "--terms", "4", "-o",
                dir.resolve("T").toString());
        assertFalse(err(precompute).contains("lambda/"), err(precompute));
        Object[] at30 = run("brdfmap", "--patch", patch.toString(), "--theta-i", "30", "--variant", "flss", "--terms",
                "4", "--terms-dir", dir.resolve("T").toString(), "--size", "8", "-o", dir.resolve("m.png").toString());
        assertFalse(err(at30).contains("lambda/"), err(at30));
        Object[] at75 = run("brdfmap", "--patch", patch.toString(), "--theta-i", "75", "--variant", "flss", "--terms",
                "4", "--terms-dir", dir.resolve("T").toString(), "--size", "8", "-o", dir.resolve("m.png").toString());
        List<String> notes = err(at75).lines().filter(l -> l.contains("lambda/")).toList();
        assertEquals(List.of("pixel size 0.1 um along x and y is coarser than lambda/3.932 for 380-393.2 nm: those"
                + " wavelengths alias only towards the rim of the map (views near grazing) with the light at 75"
                + " degrees; <= 0.09665 um avoids it"), notes);
    }

    /**
     * The plain series asked for on a tall patch: the warning names the expansion that avoids it, the phase-centred
     * one (on auto's calibrated path the automatic expansion is the plain series), in the settings' words.
     */
    @Test
    void thePlainSeriesWarningNamesTheCentredExpansion() throws IOException {
        Path tall = dir.resolve("tall.gsf");
        GsfWriter.write(tall, SyntheticPatches.blazed(2.5, 2.0, 50, 4, 8));
        Object[] plain = run("brdfmap", "--patch", tall.toString(), "--theta-i", "30", "--variant", "flss",
                "--expansion", "plain", "--size", "8", "-o", dir.resolve("m.png").toString());
        assertEquals(0, plain[0], err(plain));
        assertTrue(err(plain).contains("; the phase-centred expansion avoids it, as do a longer shortest wavelength"
                + " or a lower patch"), err(plain));
        assertFalse(err(plain).contains("automatic expansion"), err(plain));
    }
}
