package diffract.render;

import diffract.jrtr.GlTestSupport;
import diffract.optics.BrdfSettings;
import diffract.optics.settings.GainModel;
import diffract.optics.settings.PixelFilter;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.settings.TermFormat;
import diffract.optics.Variant;
import diffract.util.DiskCache;
import diffract.util.Reporter;
import diffract.util.TestCache;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Baked tables in the disk cache: a later "run" (a fresh in-memory cache and terms recomputed to equal content)
 * loads the table bit for bit without baking; a damaged entry is said in one warning and baked again; a table on
 * disk is at hand for the viewer without a bake; a disabled cache writes nothing; and the key changes with every
 * input that changes the table. Each test has a cache folder of its own.
 */
class BakedTableDiskCacheTest {
    @TempDir
    Path dir;
    private TestCache cache;
    /** The tables of one pipeline. */
    private BakedTables tables;

    @BeforeEach
    void ownCache() {
        cache = TestCache.at(dir.resolve("cache"));
        tables = new BakedTables();
    }

    @AfterEach
    void backToTheBuildsCache() {
        cache.close();
        tables.forgetInMemory();
    }

    /** A small table: 9 x 9 x 2 samples at 20 nm bake in well under a second on llvmpipe. */
    private static BrdfSettings small() {
        return RenderTestSupport.settings(Variant.BAKED).with(b -> b.bakedSamples(9, 2).lambdaStepNm(20));
    }

    /** The same terms as a new run computes them: equal content, another object. */
    private static TaylorTerms recomputed(TaylorTerms terms) {
        float[][] data = new float[terms.termCount()][];
        for (int n = 0; n < data.length; n++) {
            data[n] = terms.termData(n);
        }
        return new TaylorTerms(terms.rows(), terms.cols(), terms.pixelSizeXUm(), terms.pixelSizeYUm(),
                terms.maxAbsHeightUm(), data);
    }

    private List<Path> entries() throws IOException {
        Path tables = dir.resolve("cache").resolve(BakedTableFile.KIND);
        if (!Files.isDirectory(tables)) {
            return List.of();
        }
        try (Stream<Path> files = Files.list(tables)) {
            return files.filter(p -> p.toString().endsWith(DiskCache.ENTRY_SUFFIX)).toList();
        }
    }

    private static int[] bits(float[] values) {
        int[] bits = new int[values.length];
        for (int i = 0; i < values.length; i++) {
            bits[i] = Float.floatToRawIntBits(values[i]);
        }
        return bits;
    }

    /** FLSS's table (a point light) and the lobes method's (a pixel box): each stored once and loaded bit for bit. */
    @Test
    void aStoredTableLoadsBitForBitWithoutABake() throws IOException {
        GlTestSupport.assumeOffscreenGl();
        TaylorTerms terms = RenderTestSupport.terms(RenderTestSupport.BLAZED);
        List<BrdfSettings> methods = List.of(small(), small().with(b -> b.pixelFilter(PixelFilter.BOX)));
        assertEquals(Variant.FLSS, BakedTables.tabulated(terms, methods.get(0)));
        assertEquals(Variant.LOBES, BakedTables.tabulated(terms, methods.get(1)));
        for (BrdfSettings settings : methods) {
            int bakes = tables.bakeCount();
            Reporter.Collecting first = new Reporter.Collecting();
            BakedTable baked = tables.of(terms, settings, first);
            assertEquals(bakes + 1, tables.bakeCount(), "the first run bakes");
            assertTrue(first.infos().stream().anyMatch(s -> s.startsWith("stored the table baked in")
                    && s.contains(BakedTableFile.KIND)), first.infos().toString());

            tables.forgetInMemory(); // a new process
            int loads = tables.loadCount();
            Reporter.Collecting second = new Reporter.Collecting();
            BakedTable loaded = tables.of(recomputed(terms), settings, second);
            assertEquals(bakes + 1, tables.bakeCount(), "a later run does not bake");
            assertEquals(loads + 1, tables.loadCount());
            assertTrue(second.infos().stream().anyMatch(s -> s.startsWith("loaded the 9 x 9 x 2 table")
                    && s.contains("from the disk cache")), second.infos().toString());
            assertTrue(second.warnings().isEmpty(), second.warnings().toString());
            assertEquals(baked.grid(), loaded.grid());
            assertEquals(baked.filtered(), loaded.filtered());
            assertEquals(baked.precision(), loaded.precision());
            assertEquals(baked.bakeSeconds(), loaded.bakeSeconds());
            assertArrayEquals(bits(baked.values()), bits(loaded.values()), "bit for bit");
        }
        assertEquals(2, entries().size(), "one entry per table");
    }

    /** Flipped bytes and a truncated file: one warning each, the table is baked again and stored whole. */
    @Test
    void aDamagedEntryIsSaidAndBakedAgain() throws IOException {
        GlTestSupport.assumeOffscreenGl();
        TaylorTerms terms = RenderTestSupport.terms(RenderTestSupport.BLAZED);
        float[] expected = tables.of(terms, small(), Reporter.SILENT).values();
        Path entry = entries().get(0);
        byte[] good = Files.readAllBytes(entry);
        byte[] flipped = good.clone();
        flipped[good.length / 2] ^= (byte) 0xff;
        flipped[good.length / 2 + 1] ^= (byte) 0xff;
        for (byte[] damaged : List.of(flipped, Arrays.copyOf(good, good.length - 200))) {
            Files.write(entry, damaged);
            tables.forgetInMemory();
            int bakes = tables.bakeCount();
            Reporter.Collecting reporter = new Reporter.Collecting();
            BakedTable again = tables.of(recomputed(terms), small(), reporter);
            assertEquals(bakes + 1, tables.bakeCount(), "a damaged entry is baked again");
            assertEquals(1, reporter.warnings().size(), reporter.warnings().toString());
            String warning = reporter.warnings().get(0);
            assertTrue(warning.startsWith(entry + " is damaged (") && warning.endsWith("): baking the table again"),
                    warning);
            assertArrayEquals(bits(expected), bits(again.values()));
            tables.forgetInMemory();
            Reporter.Collecting repaired = new Reporter.Collecting();
            tables.of(recomputed(terms), small(), repaired);
            assertEquals(bakes + 1, tables.bakeCount(), "the entry is whole again");
            assertTrue(repaired.warnings().isEmpty(), repaired.warnings().toString());
        }
    }

    /** The viewer's question: a table on disk is at hand without a bake; one that is not is not. */
    @Test
    void aTableOnDiskIsAtHandWithoutABake() {
        GlTestSupport.assumeOffscreenGl();
        TaylorTerms terms = RenderTestSupport.terms(RenderTestSupport.BLAZED);
        int bakes = tables.bakeCount();
        assertEquals(Optional.empty(), tables.ofStored(terms, small(), Reporter.SILENT));
        assertFalse(tables.isBaked(terms, small()));
        assertEquals(bakes, tables.bakeCount(), "asking does not bake");
        tables.of(terms, small(), Reporter.SILENT);
        tables.forgetInMemory();
        TaylorTerms again = recomputed(terms);
        assertTrue(tables.ofStored(again, small(), Reporter.SILENT).isPresent());
        assertTrue(tables.isBaked(again, small()), "loaded into memory");
        assertEquals(bakes + 1, tables.bakeCount());
    }

    /** With the disk cache off (--no-cache), a bake neither reads nor writes the cache folder. */
    @Test
    void aDisabledCacheLeavesTheFolderAlone() {
        GlTestSupport.assumeOffscreenGl();
        TaylorTerms terms = RenderTestSupport.terms(RenderTestSupport.BLAZED);
        DiskCache.useDisk(false);
        try {
            int bakes = tables.bakeCount();
            tables.of(terms, small(), Reporter.SILENT);
            tables.forgetInMemory();
            tables.of(terms, small(), Reporter.SILENT);
            assertEquals(bakes + 2, tables.bakeCount(), "nothing is read: baked again");
            assertFalse(Files.exists(dir.resolve("cache")), "nothing is written");
        } finally {
            DiskCache.useDisk(true);
        }
    }

    /**
     * The key: equal for equal terms content and for settings the table does not depend on (variant, term format,
     * Fresnel model: the in-memory key's normalisation); different for anything the table depends on.
     */
    @Test
    void theKeyFollowsEveryInputOfTheTable() {
        TaylorTerms terms = RenderTestSupport.terms(RenderTestSupport.BLAZED);
        BrdfSettings s = small().with(b -> b.variant(Variant.BAKED).termFormat(TermFormat.RG32F)
                .gain(GainModel.STAM));
        DiskCache.Key key = BakedTableFile.key(terms, s, Variant.FLSS);
        assertEquals(key, BakedTableFile.key(recomputed(terms), s, Variant.FLSS), "equal content, equal key");
        for (BrdfSettings other : List.of(s.with(b -> b.lambdaStepNm(10)), s.with(b -> b.bakedSamples(11, 2)),
                s.with(b -> b.bakedSamples(9, 3)), s.with(b -> b.coherenceLengthUm(20)),
                s.with(b -> b.refractiveIndex(1.6)), s.with(b -> b.windowRadius(2)))) {
            assertNotEquals(key, BakedTableFile.key(terms, other, Variant.FLSS), other.toString());
        }
        assertNotEquals(key, BakedTableFile.key(terms, s, Variant.LOBES), "the method");
        float[][] data = new float[terms.termCount()][];
        for (int n = 0; n < data.length; n++) {
            data[n] = terms.termData(n);
        }
        data[1][0] = Math.nextUp(data[1][0]); // one float in the last bit
        TaylorTerms other = new TaylorTerms(terms.rows(), terms.cols(), terms.pixelSizeXUm(), terms.pixelSizeYUm(),
                terms.maxAbsHeightUm(), data);
        assertNotEquals(key, BakedTableFile.key(other, s, Variant.FLSS), "other terms");
        assertNotEquals(key.fileName(), BakedTableFile.key(terms, s, Variant.LOBES).fileName());
    }
}
