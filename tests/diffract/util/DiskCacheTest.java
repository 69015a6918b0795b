package diffract.util;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.DataInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.time.Instant;
import java.time.ZoneId;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Random;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The disk cache on its own: entries read back bit for bit, damage is found and said once, concurrent writers leave
 * one whole entry, the least recently used entries go first (with a clock the test moves, so nothing depends on
 * timing), and a disabled cache touches nothing.
 */
class DiskCacheTest {
    static final DiskCache.Key SHARED_KEY = new DiskCache.Key("baked-tables", "shared test entry");

    /** A clock that moves one second each time it is read: every use is later than the one before. */
    static final class SteppingClock extends Clock {
        private Instant now = Instant.parse("2020-01-01T00:00:00Z");

        @Override
        public synchronized Instant instant() {
            now = now.plusSeconds(1);
            return now;
        }

        @Override
        public ZoneId getZone() {
            return ZoneOffset.UTC;
        }

        @Override
        public Clock withZone(ZoneId zone) {
            return this;
        }
    }

    /** 1 M floats the shared entry holds (4 MB: writers overlap). */
    static float[] sharedPayload() {
        float[] values = new float[1 << 20];
        for (int i = 0; i < values.length; i++) {
            values[i] = (float) Math.sin(i * 1e-3);
        }
        return values;
    }

    static float[] readShared(DataInputStream in) throws IOException {
        float[] values = new float[1 << 20];
        DiskCache.readFloats(in, values);
        return values;
    }

    private static float[] randomFloats(int n, long seed) {
        Random random = new Random(seed);
        float[] values = new float[n];
        for (int i = 0; i < n; i++) {
            values[i] = Float.intBitsToFloat(random.nextInt()); // every bit pattern, NaNs and infinities too
        }
        return values;
    }

    private static int[] bits(float[] values) {
        int[] bits = new int[values.length];
        for (int i = 0; i < values.length; i++) {
            bits[i] = Float.floatToRawIntBits(values[i]);
        }
        return bits;
    }

    private static DiskCache.Reader<float[]> floats(int n) {
        return in -> {
            float[] values = new float[n];
            DiskCache.readFloats(in, values);
            return values;
        };
    }

    private static DiskCache.Key key(String name) {
        return new DiskCache.Key("reference-maps", "test entry " + name);
    }

    private static Optional<Path> store(DiskCache cache, DiskCache.Key key, float[] values, Reporter reporter) {
        return cache.store(key, out -> DiskCache.writeFloats(out, values), "the test entry", reporter);
    }

    private static List<Path> files(Path dir) throws IOException {
        if (!Files.exists(dir)) {
            return List.of();
        }
        try (Stream<Path> all = Files.walk(dir)) {
            return all.filter(Files::isRegularFile).sorted().toList();
        }
    }

    @Test
    void anEntryReadsBackBitForBit(@TempDir Path root) {
        DiskCache cache = DiskCache.at(root, Long.MAX_VALUE, new SteppingClock());
        float[] values = randomFloats(100_003, 1);
        Path file = store(cache, key("a"), values, Reporter.SILENT).orElseThrow();
        assertEquals(root.resolve("reference-maps").resolve(key("a").fileName()), file);
        Reporter.Collecting reporter = new Reporter.Collecting();
        float[] back = cache.load(key("a"), floats(values.length), reporter, "again");
        assertArrayEquals(bits(values), bits(back));
        assertTrue(reporter.warnings().isEmpty(), reporter.warnings().toString());
        assertNull(cache.load(key("b"), floats(1), reporter, "again"), "another key finds nothing");
    }

    @Test
    void aDamagedEntryIsSaidOnceRemovedAndStoredAgain(@TempDir Path root) throws IOException {
        DiskCache cache = DiskCache.at(root, Long.MAX_VALUE, new SteppingClock());
        float[] values = randomFloats(10_000, 2);
        Path file = store(cache, key("a"), values, Reporter.SILENT).orElseThrow();
        byte[] good = Files.readAllBytes(file);
        record Damage(String name, byte[] bytes, String said) {
        }
        byte[] flipped = good.clone();
        for (int i = 0; i < 4; i++) {
            flipped[good.length / 2 + i] ^= (byte) 0x5a;
        }
        byte[] header = good.clone();
        header[3] ^= 1;
        List<Damage> damages = List.of(
                new Damage("flipped payload bytes", flipped, "fails its checksum"),
                new Damage("an altered header", header, "fails its checksum"),
                new Damage("truncated by half", java.util.Arrays.copyOf(good, good.length / 2), "truncated"),
                new Damage("truncated by one byte", java.util.Arrays.copyOf(good, good.length - 1), "truncated"),
                new Damage("empty", new byte[0], "truncated"));
        for (Damage damage : damages) {
            Files.write(file, damage.bytes());
            Reporter.Collecting reporter = new Reporter.Collecting();
            assertNull(cache.load(key("a"), floats(values.length), reporter, "computing it again"), damage.name());
            assertEquals(1, reporter.warnings().size(), damage.name() + ": " + reporter.warnings());
            String warning = reporter.warnings().get(0);
            assertTrue(warning.startsWith(file + " is damaged (") && warning.contains(damage.said())
                    && warning.endsWith("): computing it again"), damage.name() + ": " + warning);
            assertFalse(Files.exists(file), damage.name() + ": the damaged entry is removed");
            store(cache, key("a"), values, Reporter.SILENT).orElseThrow();
            assertArrayEquals(bits(values), bits(cache.load(key("a"), floats(values.length), reporter, "again")),
                    damage.name() + ": repaired");
        }
    }

    /** A reader that finds the payload wrong (another grid, a short array) makes the entry damaged too. */
    @Test
    void aPayloadItsReaderRefusesIsDamaged(@TempDir Path root) {
        DiskCache cache = DiskCache.at(root, Long.MAX_VALUE, new SteppingClock());
        store(cache, key("a"), randomFloats(100, 3), Reporter.SILENT).orElseThrow();
        Reporter.Collecting shorter = new Reporter.Collecting();
        assertNull(cache.load(key("a"), floats(50), shorter, "again"));
        assertTrue(shorter.warnings().get(0).contains("200 bytes longer than its reader reads"),
                shorter.warnings().toString());
        store(cache, key("a"), randomFloats(100, 3), Reporter.SILENT).orElseThrow();
        Reporter.Collecting longer = new Reporter.Collecting();
        assertNull(cache.load(key("a"), floats(101), longer, "again"));
        assertTrue(longer.warnings().get(0).contains("its payload does not read: it ends early"),
                longer.warnings().toString());
    }

    /** Threads storing one key at once, while others read it: every read is whole, one entry and no temporary is left. */
    @Test
    void concurrentThreadsStoringOneKeyLeaveOneValidEntry(@TempDir Path root) throws Exception {
        DiskCache cache = DiskCache.at(root, Long.MAX_VALUE, Clock.systemUTC());
        float[] values = sharedPayload();
        int threads = 4;
        CountDownLatch start = new CountDownLatch(1);
        ExecutorService pool = Executors.newFixedThreadPool(threads);
        Reporter.Collecting reporter = new Reporter.Collecting();
        try {
            List<Future<Integer>> done = new ArrayList<>();
            for (int t = 0; t < threads; t++) {
                done.add(pool.submit(() -> {
                    start.await();
                    int whole = 0;
                    for (int i = 0; i < 5; i++) {
                        store(cache, SHARED_KEY, values, reporter).orElseThrow();
                        float[] back = cache.load(SHARED_KEY, DiskCacheTest::readShared, reporter, "again");
                        whole += java.util.Arrays.equals(back, values) ? 1 : 0;
                    }
                    return whole;
                }));
            }
            start.countDown();
            for (Future<Integer> f : done) {
                assertEquals(5, f.get(), "every load read a whole entry");
            }
        } finally {
            pool.shutdownNow();
        }
        assertTrue(reporter.warnings().isEmpty(), reporter.warnings().toString());
        assertEquals(List.of(cache.file(SHARED_KEY)), files(root.resolve("baked-tables")));
        assertArrayEquals(values, cache.load(SHARED_KEY, DiskCacheTest::readShared, reporter, "again"));
    }

    /** Two processes (the OS locks and renames, not this JVM's threads) storing one key: one whole entry. */
    @Test
    void concurrentProcessesStoringOneKeyLeaveOneValidEntry(@TempDir Path root) throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<Process> processes = new ArrayList<>();
        for (int p = 0; p < 2; p++) {
            processes.add(new ProcessBuilder(java, "-Xmx256m", "-cp", System.getProperty("java.class.path"),
                    DiskCacheWriter.class.getName(), root.toString(), "8").redirectErrorStream(true).start());
        }
        for (Process p : processes) {
            String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertEquals(0, p.waitFor(), "a writer read a broken entry: " + output);
        }
        DiskCache cache = DiskCache.at(root, Long.MAX_VALUE, Clock.systemUTC());
        assertEquals(List.of(cache.file(SHARED_KEY)), files(root.resolve("baked-tables")));
        Reporter.Collecting reporter = new Reporter.Collecting();
        assertArrayEquals(sharedPayload(), cache.load(SHARED_KEY, DiskCacheTest::readShared, reporter, "again"));
        assertTrue(reporter.warnings().isEmpty(), reporter.warnings().toString());
    }

    /**
     * Over its limit, the cache removes the least recently used entries: a store and a reuse both count as use. Three
     * entries fit; after a, b, c, a reuse of a and a store of d, b is the one removed; then e removes c.
     */
    @Test
    void theLeastRecentlyUsedEntriesAreEvictedFirst(@TempDir Path root) throws IOException {
        float[] values = randomFloats(25_000, 4);
        long entryBytes = Files.size(store(DiskCache.at(root.resolve("probe"), Long.MAX_VALUE, new SteppingClock()),
                key("a"), values, Reporter.SILENT).orElseThrow());
        DiskCache cache = DiskCache.at(root.resolve("cache"), 3 * entryBytes + entryBytes / 2, new SteppingClock());
        for (String name : List.of("a", "b", "c")) {
            store(cache, key(name), values, Reporter.SILENT).orElseThrow();
        }
        assertNotNull(cache.load(key("a"), floats(values.length), Reporter.SILENT, "again"), "a is used again");
        Reporter.Collecting reporter = new Reporter.Collecting();
        store(cache, key("d"), values, reporter).orElseThrow();
        assertTrue(Files.exists(cache.file(key("a"))) && Files.exists(cache.file(key("c")))
                && Files.exists(cache.file(key("d"))), "a, c and d stay");
        assertFalse(Files.exists(cache.file(key("b"))), "b, the least recently used, is removed");
        assertEquals(1, reporter.infos().size(), reporter.infos().toString());
        assertTrue(reporter.infos().get(0).contains("removed the 1 least recently used entry"), reporter.infos().get(0));
        store(cache, key("e"), values, Reporter.SILENT).orElseThrow();
        assertFalse(Files.exists(cache.file(key("c"))), "then c");
        assertTrue(Files.exists(cache.file(key("a"))) && Files.exists(cache.file(key("d")))
                && Files.exists(cache.file(key("e"))));
    }

    /** A folder entry (the Taylor terms) counts all its files and goes whole; an entry over the limit is not kept. */
    @Test
    void folderEntriesCountWholeAndAnEntryLargerThanTheLimitIsNotKept(@TempDir Path root) throws IOException {
        DiskCache cache = DiskCache.at(root, 100_000, new SteppingClock());
        Path terms = cache.folderEntry("terms", "abc-n3");
        Files.createDirectories(terms);
        Files.write(terms.resolve("terms.f32"), new byte[60_000]);
        Files.write(terms.resolve("terms.json"), new byte[1_000]);
        assertTrue(cache.stored(terms, "the terms", Reporter.SILENT));
        Reporter.Collecting reporter = new Reporter.Collecting();
        store(cache, key("a"), randomFloats(10_000, 5), reporter).orElseThrow(); // 40 kB: the folder's 61 kB goes
        assertFalse(Files.exists(terms), "the least recently used folder is removed whole");
        assertTrue(Files.exists(cache.file(key("a"))));
        Reporter.Collecting tooLarge = new Reporter.Collecting();
        assertEquals(Optional.empty(), store(cache, key("big"), randomFloats(30_000, 6), tooLarge));
        assertFalse(Files.exists(cache.file(key("big"))));
        assertTrue(Files.exists(cache.file(key("a"))), "nothing else is removed for an entry that cannot fit");
        assertTrue(tooLarge.infos().stream().anyMatch(s -> s.contains("the test entry takes")
                && s.contains("it is not kept")), tooLarge.infos().toString());
    }

    /** What a killed writer left (its process is gone) is removed; a live writer's temporary file is not. */
    @Test
    void temporaryFilesOfEndedWritersAreRemoved(@TempDir Path root) throws Exception {
        DiskCache cache = DiskCache.at(root, Long.MAX_VALUE, new SteppingClock());
        Process ended = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-version").start();
        ended.waitFor();
        Path dir = Files.createDirectories(root.resolve("baked-tables"));
        Path gone = Files.write(dir.resolve("x.entry" + FolderLock.TEMPORARY_MARK + ended.pid() + "-1"), new byte[10]);
        Path live = Files.write(dir.resolve("y.entry" + FolderLock.TEMPORARY_MARK + ProcessHandle.current().pid()
                + "-1"), new byte[10]);
        store(cache, key("a"), randomFloats(10, 7), Reporter.SILENT).orElseThrow();
        assertFalse(Files.exists(gone), "an ended writer's leftover");
        assertTrue(Files.exists(live), "a live writer's file");
    }

    @Test
    void aDisabledCacheReadsAndWritesNothing(@TempDir Path root) throws IOException {
        DiskCache.useDisk(false);
        try (TestCache ignored = TestCache.at(root.resolve("cache"))) {
            DiskCache.useDisk(false); // TestCache.at switches the disk on; --no-cache switches it off
            DiskCache cache = DiskCache.user();
            assertFalse(cache.enabled());
            assertEquals(Optional.empty(), store(cache, key("a"), randomFloats(10, 8), Reporter.SILENT));
            assertNull(cache.load(key("a"), floats(10), Reporter.SILENT, "again"));
            assertFalse(Files.exists(root.resolve("cache")));
        } finally {
            DiskCache.useDisk(true);
        }
        assertTrue(DiskCache.user().enabled());
    }

    @Test
    void theLimitIsReadFromTheEnvironmentOrItsPropertyAndRefusedWhenNotASize() {
        String before = System.getProperty(DiskCache.LIMIT_PROPERTY);
        try {
            System.setProperty(DiskCache.LIMIT_PROPERTY, "5");
            assertEquals(5L << 20, DiskCache.limitBytes());
            for (String bad : List.of("0", "-3", "2GB", "1.5")) {
                System.setProperty(DiskCache.LIMIT_PROPERTY, bad);
                UserInputException e = assertThrows(UserInputException.class, DiskCache::limitBytes, bad);
                assertTrue(e.getMessage().contains("size limit in MB") && e.getMessage().contains("'" + bad + "'"),
                        e.getMessage());
            }
            System.clearProperty(DiskCache.LIMIT_PROPERTY);
            if (System.getenv(DiskCache.LIMIT_VARIABLE) == null) {
                assertEquals(DiskCache.DEFAULT_LIMIT_MB << 20, DiskCache.limitBytes());
            }
        } finally {
            if (before == null) {
                System.clearProperty(DiskCache.LIMIT_PROPERTY);
            } else {
                System.setProperty(DiskCache.LIMIT_PROPERTY, before);
            }
        }
    }

    @Test
    void keysAreOneLineOfAKnownKind() {
        assertThrows(IllegalArgumentException.class, () -> new DiskCache.Key("elsewhere", "x"));
        assertThrows(IllegalArgumentException.class, () -> new DiskCache.Key("terms", "two\nlines"));
        assertFalse(key("a").fileName().equals(key("b").fileName()));
        assertTrue(key("a").fileName().matches("[0-9a-f]{32}\\.entry"));
    }
}
