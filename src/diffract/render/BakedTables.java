package diffract.render;

import diffract.optics.BrdfSettings;
import diffract.optics.FresnelModel;
import diffract.optics.LobeQuadrature;
import diffract.optics.TaylorTerms;
import diffract.optics.TermFormat;
import diffract.optics.Variant;
import diffract.util.Reporter;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;

/**
 * Baked tables cached in memory per (patch terms, settings), so a viewer or a benchmark that draws the same patch
 * again never bakes twice. Terms are compared by identity (they are immutable); settings by value, with the
 * variant, the term format and the Fresnel model ignored (the table is FLSS's or the lobes method's on float32
 * terms whatever variant asks, before the gain factor). The least recently used table is dropped beyond
 * {@link #MAX_TABLES}: a table can take hundreds of MB. Thread-safe; a request for a table being baked waits for
 * that bake.
 */
public final class BakedTables {
    /** Tables kept at once. */
    public static final int MAX_TABLES = 2;

    private record Key(TaylorTerms terms, BrdfSettings settings, boolean lobes) {
        @Override
        public boolean equals(Object o) {
            return o instanceof Key k && k.terms == terms && k.settings.equals(settings) && k.lobes == lobes;
        }

        @Override
        public int hashCode() {
            return System.identityHashCode(terms) * 31 + settings.hashCode();
        }
    }

    private static final Map<Key, BakedTable> CACHE = new LinkedHashMap<>(4, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Key, BakedTable> eldest) {
            return size() > MAX_TABLES;
        }
    };
    /** Bakes under way: a second caller waits for the first one's table instead of baking it again. */
    private static final Map<Key, CompletableFuture<BakedTable>> BAKING = new HashMap<>();
    private static int bakes;

    private BakedTables() {
    }

    /**
     * The table of these terms and settings, baked on the first request: of the lobes method, cell- and
     * light-averaged, when the illumination filters (a pixel box or a light) and the lobes shader can take the patch
     * (no texel pairs); else of FLSS. The bake runs outside the cache's lock, so {@link #isBaked} answers at once
     * while a table bakes.
     */
    public static BakedTable of(TaylorTerms terms, BrdfSettings settings, Reporter reporter) {
        Key key = key(terms, settings);
        CompletableFuture<BakedTable> mine = null;
        CompletableFuture<BakedTable> pending;
        synchronized (BakedTables.class) {
            BakedTable table = CACHE.get(key);
            if (table != null) {
                return table;
            }
            pending = BAKING.get(key);
            if (pending == null) {
                mine = new CompletableFuture<>();
                BAKING.put(key, mine);
                pending = mine;
            }
        }
        if (mine != null) {
            try {
                BakedTable table = bakeOffThisThread(terms, settings, key.lobes(), reporter);
                synchronized (BakedTables.class) {
                    CACHE.put(key, table);
                    bakes++;
                    BAKING.remove(key);
                }
                mine.complete(table);
            } catch (RuntimeException | Error e) {
                synchronized (BakedTables.class) {
                    BAKING.remove(key);
                }
                mine.completeExceptionally(e);
                throw e;
            }
        }
        try {
            return pending.join();
        } catch (CompletionException e) {
            throw e.getCause() instanceof RuntimeException r ? r : e;
        }
    }

    /** Whether the table of these terms and settings is baked and cached (answers at once, even during a bake). */
    public static synchronized boolean isBaked(TaylorTerms terms, BrdfSettings settings) {
        return CACHE.containsKey(key(terms, settings));
    }

    /** The table is made on float32 terms before the gain factor, whatever variant, term format and Fresnel ask. */
    private static Key key(TaylorTerms terms, BrdfSettings settings) {
        return new Key(terms, settings.with(b -> b.variant(Variant.BAKED).termFormat(TermFormat.RG32F)
                .fresnel(FresnelModel.PHYSICAL)), bakesLobes(terms, settings));
    }

    /** Whether {@link #of} bakes the lobes method (else FLSS). */
    static boolean bakesLobes(TaylorTerms terms, BrdfSettings settings) {
        if (!settings.illumination().filters()) {
            return false;
        }
        return LobeQuadrature.wholeTexelsRefusal(settings, terms.cols() * terms.pixelSizeXUm(),
                terms.rows() * terms.pixelSizeYUm()).isEmpty();
    }

    /**
     * Bakes on a thread of its own when a GL context is current on this one (a render loop asking for a table it
     * has not got): the bake's hidden context then never touches the caller's context or framebuffer bindings
     * (making the caller's context current again lets JOGL rebind its own framebuffer, and the frame came out
     * black). The caller waits for the table.
     */
    private static BakedTable bakeOffThisThread(TaylorTerms terms, BrdfSettings settings, boolean lobes,
                                                Reporter reporter) {
        if (com.jogamp.opengl.GLContext.getCurrent() == null) {
            return BakedTable.bake(terms, settings, lobes, BakedTable.PRECISION, reporter);
        }
        java.util.concurrent.CompletableFuture<BakedTable> bake = java.util.concurrent.CompletableFuture.supplyAsync(
                () -> BakedTable.bake(terms, settings, lobes, BakedTable.PRECISION, reporter),
                command -> new Thread(command, "bake").start());
        try {
            return bake.join();
        } catch (CompletionException e) {
            throw e.getCause() instanceof RuntimeException r ? r : e;
        }
    }

    /** How many tables were baked so far (tests: the cache bakes once). */
    public static synchronized int bakeCount() {
        return bakes;
    }
}
