package diffract.render;

import diffract.jrtr.contexts.HeadlessGL;
import diffract.optics.BakedGrid;
import diffract.optics.BrdfSettings;
import diffract.optics.settings.GainModel;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.settings.TermFormat;
import diffract.optics.Variant;
import diffract.util.DiskCache;
import diffract.util.Reporter;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;

/**
 * Baked tables cached in memory per (patch terms, settings), so a viewer or a benchmark that draws the same patch
 * again never bakes twice (each pipeline, the layer above, owns one cache for its patch), and on disk
 * ({@link DiskCache}, {@link BakedTableFile}), so a later run loads the table instead of baking it. In memory,
 * terms are compared by identity (they are immutable); on disk, by their content hash. Settings are compared by
 * value, with the variant, the term format and the Fresnel model ignored (the table is that of the method it
 * tabulates on float32 terms, whatever table method asks, before the gain factor). The least recently used table is
 * dropped from memory beyond {@link #MAX_TABLES} per cache: a table can take hundreds of MB.
 * Thread-safe; a request for a table being baked (or loaded) waits for that bake.
 */
public final class BakedTables {
    /** Tables kept at once. */
    public static final int MAX_TABLES = 2;

    private record Key(TaylorTerms terms, BrdfSettings settings, Variant tabulated) {
        @Override
        public boolean equals(Object o) {
            return o instanceof Key k && k.terms == terms && k.settings.equals(settings)
                    && k.tabulated.equals(tabulated);
        }

        @Override
        public int hashCode() {
            return System.identityHashCode(terms) * 31 + settings.hashCode();
        }
    }

    private final Map<Key, BakedTable> inMemory = new LinkedHashMap<>(4, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Key, BakedTable> eldest) {
            return size() > MAX_TABLES;
        }
    };
    /** Bakes under way: a second caller waits for the first one's table instead of baking it again. */
    private final Map<Key, CompletableFuture<BakedTable>> baking = new HashMap<>();
    /**
     * Disk keys already worked out (they preprocess the bake's shaders), by the terms' content hash, settings and
     * method: not by the terms themselves, which would keep large terms alive.
     */
    private final Map<String, DiskCache.Key> diskKeys = new LinkedHashMap<>(16, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, DiskCache.Key> eldest) {
            return size() > 16;
        }
    };
    private int bakes;
    private int loads;

    /** An empty cache: a pipeline's own (every table of its patch), or a caller's that draws without one. */
    public BakedTables() {
    }

    /**
     * The table of these terms and settings, loaded from the disk cache or baked on the first request: of the method
     * the settings' table method holds for the patch ({@link Variant#tabulated}; plain {@code baked}: the lobes
     * method, cell- and light-averaged, when the illumination filters and the lobes shader takes the patch, else
     * FLSS). A baked table is stored in the disk cache. The bake runs outside the cache's lock, so {@link #isBaked}
     * answers at once while a table bakes.
     */
    public BakedTable of(TaylorTerms terms, BrdfSettings settings, Reporter reporter) {
        Key key = key(terms, settings);
        while (true) {
            CompletableFuture<BakedTable> mine = null;
            CompletableFuture<BakedTable> pending;
            synchronized (this) {
                BakedTable table = inMemory.get(key);
                if (table != null) {
                    return table;
                }
                pending = baking.get(key);
                if (pending == null) {
                    mine = new CompletableFuture<>();
                    baking.put(key, mine);
                    pending = mine;
                }
            }
            if (mine != null) {
                try {
                    BakedTable table = loadOrBake(terms, settings, key, reporter);
                    synchronized (this) {
                        inMemory.put(key, table);
                        baking.remove(key);
                    }
                    mine.complete(table);
                } catch (RuntimeException | Error e) {
                    synchronized (this) {
                        baking.remove(key);
                    }
                    mine.completeExceptionally(e);
                    throw e;
                }
            }
            try {
                BakedTable table = pending.join();
                if (table != null) {
                    return table;
                }
                // null: ofStored found no sound table on disk; this caller bakes it
            } catch (CompletionException e) {
                throw e.getCause() instanceof RuntimeException r ? r : e;
            }
        }
    }

    /**
     * The table of these terms and settings if it is at hand without a bake: in memory, or in the disk cache (then
     * loaded now, in a fraction of a second); empty when it would have to be baked, or is being baked. The viewer
     * asks this to draw a table from disk at once instead of previewing while it "bakes".
     */
    public Optional<BakedTable> ofStored(TaylorTerms terms, BrdfSettings settings, Reporter reporter) {
        Key key = key(terms, settings);
        synchronized (this) {
            BakedTable table = inMemory.get(key);
            if (table != null || baking.containsKey(key)) {
                return Optional.ofNullable(table);
            }
        }
        DiskCache cache = DiskCache.user();
        if (!cache.enabled()) {
            return Optional.empty();
        }
        DiskCache.Key diskKey = diskKey(key);
        if (!Files.isRegularFile(cache.file(diskKey))) {
            return Optional.empty();
        }
        CompletableFuture<BakedTable> mine = new CompletableFuture<>();
        synchronized (this) {
            BakedTable table = inMemory.get(key);
            if (table != null || baking.containsKey(key)) {
                return Optional.ofNullable(table);
            }
            baking.put(key, mine);
        }
        BakedTable table = null;
        try {
            table = load(cache, diskKey, key, reporter);
        } finally {
            synchronized (this) {
                if (table != null) {
                    inMemory.put(key, table);
                }
                baking.remove(key);
            }
            mine.complete(table); // null: a caller of of() that waited bakes the table itself
        }
        return Optional.ofNullable(table);
    }

    /** The table from the disk cache, else baked now (and then stored there). */
    private BakedTable loadOrBake(TaylorTerms terms, BrdfSettings settings, Key key, Reporter reporter) {
        DiskCache cache = DiskCache.user();
        DiskCache.Key diskKey = cache.enabled() ? diskKey(key) : null;
        if (diskKey != null) {
            BakedTable stored = load(cache, diskKey, key, reporter);
            if (stored != null) {
                return stored;
            }
        }
        BakedTable table = bakeOffThisThread(terms, settings, key.tabulated(), reporter);
        synchronized (this) {
            bakes++;
        }
        if (diskKey == null) {
            return table;
        }
        if (table.shortCells() > 0) {
            reporter.info("the table is not kept in the disk cache: " + table.shortCells() + " of its cells miss lobes"
                    + " on this GL, where another GL may bake them whole");
            return table;
        }
        Optional<Path> file = cache.store(diskKey, out -> BakedTableFile.write(table, out), "the baked table",
                reporter);
        file.ifPresent(f -> reporter.info(String.format(Locale.ROOT, "stored the table baked in %.1f s in the disk "
                + "cache: %s (%.1f MB); a later run loads it instead of baking", table.bakeSeconds(), f,
                sizeMb(f))));
        return table;
    }

    /** The table of the disk cache's entry, or null when there is none or it is damaged (then said as a warning). */
    private BakedTable load(DiskCache cache, DiskCache.Key diskKey, Key key, Reporter reporter) {
        long start = System.nanoTime();
        BakedGrid grid = BakedGrid.of(key.settings(), key.terms().maxAbsHeightUm());
        BakedTable table = cache.load(diskKey, in -> BakedTableFile.read(in, grid, key.tabulated()), reporter,
                "baking the table again");
        if (table != null) {
            synchronized (this) {
                loads++;
            }
            reporter.info(String.format(Locale.ROOT, "loaded the %s from the disk cache in %.1f s (its bake took %.1f s): "
                    + "%s", table.describe(), (System.nanoTime() - start) * 1e-9, table.bakeSeconds(),
                    cache.file(diskKey)));
        }
        return table;
    }

    private static double sizeMb(Path file) {
        try {
            return Files.size(file) / 1e6;
        } catch (java.io.IOException e) {
            return Double.NaN;
        }
    }

    /** The disk cache's key of an in-memory key, worked out once. */
    private DiskCache.Key diskKey(Key key) {
        String memo = key.terms().contentSha256() + " " + key.settings() + " " + key.tabulated().spec();
        synchronized (diskKeys) {
            DiskCache.Key known = diskKeys.get(memo);
            if (known != null) {
                return known;
            }
        }
        DiskCache.Key computed = BakedTableFile.key(key.terms(), key.settings(), key.tabulated());
        synchronized (diskKeys) {
            diskKeys.put(memo, computed);
        }
        return computed;
    }

    /** Whether the table of these terms and settings is baked and cached (answers at once, even during a bake). */
    public synchronized boolean isBaked(TaylorTerms terms, BrdfSettings settings) {
        return inMemory.containsKey(key(terms, settings));
    }

    /**
     * Whether the table of these terms and settings is baked and cached, and what a surface drawn with them reads of
     * it besides is ready ({@link BakedTable#spreadReady}: the spread by a wide disc); answers at once.
     */
    public synchronized boolean isReady(TaylorTerms terms, BrdfSettings settings) {
        BakedTable table = inMemory.get(key(terms, settings));
        return table != null && table.spreadReady(settings);
    }

    /**
     * The table is made on float32 terms before the gain factor, whatever variant, term format and Fresnel ask, and
     * with the light it holds ({@link BakedDisc#heldBy}: a point under a disc).
     */
    private static Key key(TaylorTerms terms, BrdfSettings settings) {
        return new Key(terms, BakedDisc.heldBy(settings).with(b -> b.variant(Variant.BAKED)
                .termFormat(TermFormat.RG32F).gain(GainModel.STAM)
                .rigorous(settings.rigorous().withOrders(diffract.optics.settings.OrderWeights.SCALAR))),
                tabulated(terms, settings));
    }

    /**
     * The method whose table {@link #of} holds for these terms and settings: the choice of their table method, or of
     * plain {@code baked} where they name a method that draws without one.
     */
    static Variant tabulated(TaylorTerms terms, BrdfSettings settings) {
        double widthUm = terms.cols() * terms.pixelSizeXUm();
        double heightUm = terms.rows() * terms.pixelSizeYUm();
        return settings.variant().tabulated(settings, widthUm, heightUm)
                .orElseGet(() -> Variant.BAKED.tabulated(settings, widthUm, heightUm).orElseThrow());
    }

    /**
     * Bakes on a thread of its own when a GL context is current on this one (a render loop asking for a table it
     * has not got): the bake's hidden context then never touches the caller's context or framebuffer bindings
     * (making a JOGL window's context current again lets JOGL rebind its own framebuffer, and the frame is black;
     * on NVIDIA's EGL the caller's new vertex arrays and buffers then fail to bind). The caller waits for the
     * table.
     */
    private static BakedTable bakeOffThisThread(TaylorTerms terms, BrdfSettings settings, Variant tabulated,
                                                Reporter reporter) {
        if (HeadlessGL.currentContext() == null) {
            return BakedTable.bake(terms, settings, tabulated, BakedTable.PRECISION, reporter);
        }
        java.util.concurrent.CompletableFuture<BakedTable> bake = java.util.concurrent.CompletableFuture.supplyAsync(
                () -> BakedTable.bake(terms, settings, tabulated, BakedTable.PRECISION, reporter),
                command -> new Thread(command, "bake").start());
        try {
            return bake.join();
        } catch (CompletionException e) {
            throw e.getCause() instanceof RuntimeException r ? r : e;
        }
    }

    /** How many tables were baked so far (tests: the cache bakes once). */
    public synchronized int bakeCount() {
        return bakes;
    }

    /** How many tables were loaded from the disk cache so far (tests: a stored table is not baked again). */
    public synchronized int loadCount() {
        return loads;
    }

    /** Forgets the tables in memory, as a new process starts (tests: the next request reads the disk cache). */
    public synchronized void forgetInMemory() {
        inMemory.clear();
        synchronized (diskKeys) {
            diskKeys.clear();
        }
    }
}
