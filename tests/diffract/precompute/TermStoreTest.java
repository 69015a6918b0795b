package diffract.precompute;

import diffract.optics.patches.HeightField;
import diffract.optics.NaiveDft;
import diffract.optics.spectra.TaylorTerms;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.RandomAccessFile;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The native term store: exact round trip, checksum before trust, nothing half-written is ever used. */
class TermStoreTest {
    @TempDir
    Path dir;

    private static final HeightField PATCH = NaiveDft.randomPatch(9, 14, 0.3, 0.1, 21);

    private static Precomputation.Request request(int n) {
        return new Precomputation.Request(PATCH, "random", 0.3, n, null, 380);
    }

    @Test
    void roundTripIsBitExact() throws Exception {
        TaylorTerms terms = TaylorTermComputer.compute(PATCH, 6, Reporter.SILENT);
        TermStore.write(dir, terms, new TermSidecar.Patch("random", PATCH.contentSha256(), 9, 14, 0.1, 0.1, 0.3,
                PATCH.maxAbsHeightUm()), null, "test");
        TaylorTerms back = TermStore.read(dir);
        assertEquals(7, back.termCount());
        for (int n = 0; n <= 6; n++) {
            assertArrayEquals(terms.termData(n), back.termData(n));
        }
        assertEquals(terms.maxAbsHeightUm(), back.maxAbsHeightUm(), 0);
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of("terms.f32", "terms.json"), files.map(p -> p.getFileName().toString()).sorted().toList(),
                    "no temporary files are left behind");
        }
    }

    @Test
    void aRerunReusesWithoutFftAndAChangeOfNRecomputes() {
        assertFalse(Precomputation.intoFolder(request(4), dir, false, Reporter.SILENT).reused());
        assertTrue(Precomputation.intoFolder(request(4), dir, true, Reporter.SILENT).reused());
        assertFalse(Precomputation.intoFolder(request(5), dir, false, Reporter.SILENT).reused());
    }

    @Test
    void corruptDataFailsItsChecksumAndIsRecomputedNotUsed() throws Exception {
        Precomputation.intoFolder(request(4), dir, false, Reporter.SILENT);
        try (RandomAccessFile file = new RandomAccessFile(dir.resolve("terms.f32").toFile(), "rw")) {
            file.seek(100);
            int b = file.read();
            file.seek(100);
            file.write(b ^ 0x40);
        }
        UserInputException e = assertThrows(UserInputException.class, () -> TermStore.read(dir));
        assertTrue(e.getMessage().contains("fails its checksum"), e.getMessage());
        Reporter.Collecting reporter = new Reporter.Collecting();
        Precomputation.Result result = Precomputation.intoFolder(request(4), dir, true, reporter);
        assertFalse(result.reused());
        assertTrue(reporter.warnings().get(0).contains("recomputing"), reporter.warnings().toString());
        TermStore.read(dir); // verified again
    }

    @Test
    void anInterruptedRunLeavesNothingTrusted() throws Exception {
        // a run killed after the data but before the sidecar: data and a stray temporary file, no sidecar
        Precomputation.intoFolder(request(4), dir, false, Reporter.SILENT);
        Files.delete(dir.resolve("terms.json"));
        Files.writeString(dir.resolve("terms.f32.tmp-123-456"), "partial");
        assertThrows(UserInputException.class, () -> TermStore.read(dir));
        assertFalse(Precomputation.intoFolder(request(4), dir, false, Reporter.SILENT).reused());
        // a truncated data file next to a complete sidecar is not reused either
        try (RandomAccessFile file = new RandomAccessFile(dir.resolve("terms.f32").toFile(), "rw")) {
            file.setLength(file.length() - 8);
        }
        assertFalse(Precomputation.intoFolder(request(4), dir, false, Reporter.SILENT).reused());
        TermStore.read(dir);
    }

    @Test
    void concurrentPrecomputesOfTheSamePatchDoNotCorruptTheFolder() throws Exception {
        ExecutorService pool = Executors.newFixedThreadPool(4);
        try {
            List<Future<Precomputation.Result>> futures = new ArrayList<>();
            for (int k = 0; k < 8; k++) {
                futures.add(pool.submit(() -> Precomputation.intoFolder(request(8), dir, true, Reporter.SILENT)));
            }
            for (Future<Precomputation.Result> f : futures) {
                assertEquals(9, f.get().terms().termCount());
            }
        } finally {
            pool.shutdown();
        }
        TaylorTerms terms = TermStore.read(dir);
        assertArrayEquals(TaylorTermComputer.compute(PATCH, 8, Reporter.SILENT).termData(8), terms.termData(8));
    }
}
