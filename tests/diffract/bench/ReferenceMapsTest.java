package diffract.bench;

import diffract.optics.BrdfSettings;
import diffract.optics.settings.LightProfile;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.Variant;
import diffract.util.DiskCache;
import diffract.util.Reporter;
import diffract.util.TestCache;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The bench's reference maps in the disk cache: computed once and read back bit for bit by a later run, a damaged
 * entry computed again with one warning, a disabled cache neither read nor written, other settings another entry.
 */
class ReferenceMapsTest {
    static final BenchPatch GRATING = new BenchPatch("grating",
            SyntheticPatches.blazed(2.5, 0.13, 10, 2, 4).meanSubtracted(), 0);
    static final BrdfSettings BASE = BrdfSettings.builder(Variant.FLSS).lambdaRangeNm(380, 780)
            .coherenceLengthUm(10).build();
    static final int SIZE = 8;

    private static List<Path> entries(Path root) throws IOException {
        Path dir = root.resolve(ReferenceMaps.KIND);
        if (!Files.isDirectory(dir)) {
            return List.of();
        }
        try (Stream<Path> files = Files.list(dir)) {
            return files.filter(p -> p.toString().endsWith(DiskCache.ENTRY_SUFFIX)).toList();
        }
    }

    @Test
    void aMapIsComputedOnceAndReadBackBitForBit(@TempDir Path root) throws IOException {
        Reporter.Collecting first = new Reporter.Collecting();
        ReferenceMaps.Timed computed = new ReferenceMaps(DiskCache.at(root), first).timed(GRATING, 30, SIZE, BASE);
        assertTrue(first.infos().stream().anyMatch(s -> s.startsWith("reference map grating") && s.contains("cached in")),
                first.infos().toString());
        assertEquals(1, entries(root).size());
        Reporter.Collecting second = new Reporter.Collecting();
        ReferenceMaps.Timed loaded = new ReferenceMaps(DiskCache.at(root), second).timed(GRATING, 30, SIZE, BASE);
        assertTrue(second.infos().isEmpty() && second.warnings().isEmpty(), "nothing computed: " + second.infos());
        assertArrayEquals(computed.xyz(), loaded.xyz());
        assertEquals(computed.seconds(), loaded.seconds(), "the seconds of the computation are kept");

        new ReferenceMaps(DiskCache.at(root), Reporter.SILENT).timed(GRATING, 45, SIZE, BASE);
        new ReferenceMaps(DiskCache.at(root), Reporter.SILENT).timed(GRATING, 30, SIZE, BASE.with(b ->
                b.coherenceLengthUm(20)));
        assertEquals(3, entries(root).size(), "another light or coherence, another entry");
    }

    @Test
    void aPointLightsMapHasOneKeyWhateverItsProfileAndASizedLightOnePerProfile() {
        BrdfSettings disc = BASE.with(b -> b.lightSizeDeg(0).lightProfile(LightProfile.DISC));
        BrdfSettings gaussian = BASE.with(b -> b.lightSizeDeg(0).lightProfile(LightProfile.GAUSSIAN));
        assertEquals(ReferenceMaps.key(GRATING, 30, SIZE, disc), ReferenceMaps.key(GRATING, 30, SIZE, gaussian));
        BrdfSettings wideDisc = disc.with(b -> b.lightSizeDeg(2));
        BrdfSettings wideGaussian = gaussian.with(b -> b.lightSizeDeg(2));
        assertNotEquals(ReferenceMaps.key(GRATING, 30, SIZE, wideDisc),
                ReferenceMaps.key(GRATING, 30, SIZE, wideGaussian));
    }

    @Test
    void aDamagedMapIsComputedAgainWithAWarning(@TempDir Path root) throws IOException {
        float[] good = new ReferenceMaps(DiskCache.at(root), Reporter.SILENT).xyz(GRATING, 30, SIZE, BASE);
        Path entry = entries(root).get(0);
        byte[] bytes = Files.readAllBytes(entry);
        Files.write(entry, java.util.Arrays.copyOf(bytes, bytes.length - 7));
        Reporter.Collecting reporter = new Reporter.Collecting();
        float[] again = new ReferenceMaps(DiskCache.at(root), reporter).xyz(GRATING, 30, SIZE, BASE);
        assertEquals(1, reporter.warnings().size(), reporter.warnings().toString());
        assertTrue(reporter.warnings().get(0).endsWith("): computing the reference map again"),
                reporter.warnings().get(0));
        assertArrayEquals(good, again);
        assertEquals(bytes.length, Files.size(entry), "stored whole again");
    }

    /** The user's cache with the disk switched off (as --no-cache does) reads and writes nothing. */
    @Test
    void aDisabledCacheWritesNothing(@TempDir Path root) {
        try (TestCache ignored = TestCache.at(root)) {
            DiskCache.useDisk(false);
            new ReferenceMaps(DiskCache.user(), Reporter.SILENT).xyz(GRATING, 30, SIZE, BASE);
            assertFalse(Files.exists(root.resolve(ReferenceMaps.KIND)));
        } finally {
            DiskCache.useDisk(true);
        }
    }
}
