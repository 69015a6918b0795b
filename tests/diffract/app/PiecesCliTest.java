package diffract.app;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A reference map split into pieces ({@code brdfmap --tile}), merged ({@code merge}) or run by local workers
 * ({@code submit --local}) writes the same files, byte for byte, as the map computed whole; bad piece folders are
 * refused in one line.
 */
class PiecesCliTest {
    @TempDir
    static Path dir;

    /** A small, fast reference map: a blazed grating at a short coherence length, with auto exposure. */
    static final List<String> MAP = List.of("--synthetic", "blazed", "--coherence-length", "10", "--theta-i", "30",
            "--size", "24", "--exposure", "auto");

    static Path wholePng;
    static Path wholePfm;
    static Path wholeExr;
    static Path pieces;

    @BeforeAll
    static void computeWholeAndInPieces() {
        wholePng = dir.resolve("whole.png");
        wholePfm = dir.resolve("whole.pfm");
        wholeExr = dir.resolve("whole.exr");
        ok(brdfmap("-o", wholePng.toString(), "--pfm", wholePfm.toString(), "--exr", wholeExr.toString()));
        pieces = dir.resolve("pieces");
        for (int i = 0; i < 3; i++) {
            ok(brdfmap("--tile", i + "/3", "--pieces", pieces.toString()));
        }
    }

    @Test
    void threePiecesMergeIntoTheWholeMapsFilesBitForBit() throws Exception {
        Path png = dir.resolve("merged.png");
        Path pfm = dir.resolve("merged.pfm");
        Path exr = dir.resolve("merged.exr");
        Object[] merged = ok(CliTest.run("merge", pieces.toString(), "-o", png.toString(), "--pfm", pfm.toString(),
                "--exr", exr.toString()));
        assertTrue(((String) merged[1]).startsWith("merged 3 pieces into"), (String) merged[1]);
        assertEquals(-1, Files.mismatch(wholePfm, pfm), "PFM floats differ");
        assertEquals(-1, Files.mismatch(wholePng, png), "PNG bytes differ");
        assertEquals(-1, Files.mismatch(wholeExr, exr), "OpenEXR bytes differ");
    }

    /**
     * The rigorous method's long maps split the same way: its pieces (each solving the light's orders, or reading
     * them from the cache) merge into the map computed whole, bit for bit. A cheap solve: a 20 nm band, few harmonics
     * and slabs.
     */
    @Test
    void theRigorousMethodsPiecesMergeIntoItsWholeMap() throws Exception {
        List<String> rigorous = new ArrayList<>(MAP);
        rigorous.addAll(List.of("--variant", "rigorous", "--lambda-min", "500", "--lambda-max", "520",
                "--harmonics", "8", "--layers", "4"));
        Path whole = dir.resolve("rigorous-whole.pfm");
        List<String> wholeArgs = new ArrayList<>(rigorous);
        wholeArgs.addAll(List.of("-o", dir.resolve("rigorous-whole.png").toString(), "--pfm", whole.toString()));
        ok(CliTest.run(arguments(wholeArgs)));
        Path folder = dir.resolve("rigorous-pieces");
        for (int i = 0; i < 2; i++) {
            List<String> piece = new ArrayList<>(rigorous);
            piece.addAll(List.of("--tile", i + "/2", "--pieces", folder.toString()));
            ok(CliTest.run(arguments(piece)));
        }
        Path merged = dir.resolve("rigorous-merged.pfm");
        ok(CliTest.run("merge", folder.toString(), "-o", dir.resolve("rigorous-merged.png").toString(), "--pfm",
                merged.toString()));
        assertEquals(-1, Files.mismatch(whole, merged), "the merged rigorous map's floats differ from the whole's");
    }

    @Test
    void computingAPieceAgainWritesTheSameBytes() throws Exception {
        Path again = dir.resolve("again");
        ok(brdfmap("--tile", "1/3", "--pieces", again.toString()));
        for (String name : List.of("piece-1-of-3.json", "piece-1-of-3.f32")) {
            assertArrayEquals(Files.readAllBytes(pieces.resolve(name)), Files.readAllBytes(again.resolve(name)), name);
        }
        ok(brdfmap("--tile", "1/3", "--pieces", again.toString()));
        assertEquals(-1, Files.mismatch(pieces.resolve("piece-1-of-3.f32"), again.resolve("piece-1-of-3.f32")));
        try (var files = Files.list(again)) {
            assertEquals(2, files.count(), "a piece leaves its floats and its manifest, no temporary files");
        }
    }

    @Test
    void aMissingPieceIsRefusedByName() throws Exception {
        Path folder = copyOfPieces("missing");
        Files.delete(folder.resolve("piece-2-of-3.json"));
        assertRefused(folder, "piece 2/3 is missing");
    }

    @Test
    void aPieceOfOtherSettingsIsRefusedByName() throws Exception {
        Path folder = copyOfPieces("other");
        List<String> other = new ArrayList<>(MAP);
        other.set(other.indexOf("10"), "12"); // another coherence length
        other.addAll(List.of("--tile", "1/3", "--pieces", folder.toString()));
        ok(CliTest.run(arguments(other)));
        String line = assertRefused(folder, "piece-1-of-3.json belong to another map than piece-0-of-3.json, "
                + "piece-2-of-3.json");
        assertTrue(line.contains("sigmaSpatialUm=3.0"), line); // what differs: the coherence length / 4
    }

    @Test
    void aDamagedPieceIsRefusedByName() throws Exception {
        Path folder = copyOfPieces("damaged");
        Path floats = folder.resolve("piece-0-of-3.f32");
        byte[] bytes = Files.readAllBytes(floats);
        bytes[bytes.length / 2] ^= 1;
        Files.write(floats, bytes);
        assertRefused(folder, "piece 0/3 is damaged");
    }

    @Test
    void aPieceThereTwiceIsRefusedByName() throws Exception {
        Path folder = copyOfPieces("twice");
        Files.copy(folder.resolve("piece-0-of-3.json"), folder.resolve("copy.json"));
        assertRefused(folder, "piece 0/3 (copy.json, piece-0-of-3.json) is there more than once");
    }

    @Test
    void aPieceOfAnotherSplitIsRefused() throws Exception {
        Path folder = copyOfPieces("split");
        ok(brdfmap("--tile", "0/4", "--pieces", folder.toString()));
        assertRefused(folder, "piece-0-of-4.json belong to another map");
    }

    @Test
    void tileRefusesTheOutputsThatMergeWrites() {
        Object[] result = brdfmap("--tile", "0/3", "--pieces", dir.resolve("x").toString(), "-o",
                dir.resolve("x.png").toString());
        assertEquals(2, result[0]);
        assertTrue(((String) result[2]).contains("drop them"), (String) result[2]);
        Object[] tooMany = brdfmap("--tile", "0/25", "--pieces", dir.resolve("x").toString());
        assertEquals(2, tooMany[0]);
        assertTrue(((String) tooMany[2]).contains("has only 24 rows"), (String) tooMany[2]);
    }

    /** Worker processes (the test run's class path) compute the pieces; the outputs are the whole map's. */
    @Test
    @Tag(diffract.jrtr.GlTestSupport.LONG_TAG) // a whole map by two worker processes: a long test
    void submitWithTwoLocalWorkersWritesTheWholeMapsFiles() throws Exception {
        Path png = dir.resolve("submitted.png");
        Path pfm = dir.resolve("submitted.pfm");
        Path kept = dir.resolve("kept");
        List<String> args = new ArrayList<>(List.of("submit", "--local", "2", "--piece-count", "3", "--keep-pieces",
                kept.toString(), "--", "brdfmap"));
        args.addAll(MAP);
        args.addAll(List.of("-o", png.toString(), "--pfm", pfm.toString()));
        Object[] result = ok(CliTest.run(args.toArray(String[]::new)));
        String out = (String) result[1];
        for (int i = 0; i < 3; i++) {
            assertTrue(out.contains("piece " + i + "/3 (rows "), out);
        }
        assertEquals(-1, Files.mismatch(wholePfm, pfm), "PFM floats differ");
        assertEquals(-1, Files.mismatch(wholePng, png), "PNG bytes differ");
        assertEquals(-1, Files.mismatch(pieces.resolve("piece-2-of-3.f32"), kept.resolve("piece-2-of-3.f32")));

        Path temporary = dir.resolve("submitted-2.png");
        List<String> plain = new ArrayList<>(List.of("submit", "--local", "2", "--", "brdfmap"));
        plain.addAll(MAP);
        plain.addAll(List.of("-o", temporary.toString()));
        ok(CliTest.run(plain.toArray(String[]::new)));
        assertEquals(-1, Files.mismatch(wholePng, temporary), "PNG bytes differ");
    }

    @Test
    void aMonochromaticMapMergesBitForBit() throws Exception {
        List<String> mono = List.of("--synthetic", "blazed", "--coherence-length", "10", "--theta-i", "30", "--size",
                "16", "--lambda", "550", "--exposure", "3");
        Path png = dir.resolve("mono.png");
        Path pfm = dir.resolve("mono.pfm");
        List<String> whole = new ArrayList<>(mono);
        whole.addAll(List.of("-o", png.toString(), "--pfm", pfm.toString()));
        ok(CliTest.run(arguments(whole)));
        Path folder = dir.resolve("mono");
        for (int i = 0; i < 2; i++) {
            List<String> piece = new ArrayList<>(mono);
            piece.addAll(List.of("--tile", i + "/2", "--pieces", folder.toString()));
            ok(CliTest.run(arguments(piece)));
        }
        Path mergedPng = dir.resolve("mono-merged.png");
        Path mergedPfm = dir.resolve("mono-merged.pfm");
        ok(CliTest.run("merge", folder.toString(), "-o", mergedPng.toString(), "--pfm", mergedPfm.toString()));
        assertEquals(-1, Files.mismatch(pfm, mergedPfm), "PFM floats differ");
        assertEquals(-1, Files.mismatch(png, mergedPng), "PNG bytes differ");
    }

    /** A worker that fails (here: the patch is not there) stops submit with its line and exit code, and no output. */
    @Test
    void aFailingWorkerEndsSubmitWithItsLine() {
        Path png = dir.resolve("never.png");
        Object[] result = CliTest.run("submit", "--local", "2", "--", "brdfmap", "--patch",
                dir.resolve("absent.gsf").toString(), "--theta-i", "30", "--size", "16", "-o", png.toString());
        String err = ((String) result[2]).strip();
        assertEquals(2, result[0], err);
        assertEquals(1, err.lines().count(), err);
        assertTrue(err.matches("diffract: piece [01]/2 failed \\(exit code 2\\): diffract: .*absent\\.gsf.*"), err);
        assertTrue(Files.notExists(png));
    }

    private static Object[] brdfmap(String... more) {
        List<String> args = new ArrayList<>(MAP);
        args.addAll(List.of(more));
        return CliTest.run(arguments(args));
    }

    private static String[] arguments(List<String> options) {
        List<String> args = new ArrayList<>(List.of("brdfmap"));
        args.addAll(options);
        return args.toArray(String[]::new);
    }

    private static Object[] ok(Object[] result) {
        assertEquals(0, result[0], result[1] + "\n" + result[2]);
        return result;
    }

    private static Path copyOfPieces(String name) throws Exception {
        Path folder = dir.resolve(name);
        Files.createDirectories(folder);
        try (var files = Files.list(pieces)) {
            for (Path f : files.toList()) {
                Files.copy(f, folder.resolve(f.getFileName()), StandardCopyOption.REPLACE_EXISTING);
            }
        }
        return folder;
    }

    /** merge refuses the folder: exit 2, one line, naming what is wrong; writes nothing. */
    private static String assertRefused(Path folder, String expected) {
        Path png = folder.resolveSibling(folder.getFileName() + ".png");
        Object[] result = CliTest.run("merge", folder.toString(), "-o", png.toString());
        String err = ((String) result[2]).strip();
        assertEquals(2, result[0], err);
        assertEquals(1, err.lines().count(), err);
        assertTrue(err.contains(expected), err);
        assertTrue(Files.notExists(png));
        return err;
    }
}
