package diffract.render;

import diffract.optics.BrdfSettings;
import diffract.optics.CoherenceWindow;
import diffract.optics.FresnelModel;
import diffract.optics.LobeQuadrature;
import diffract.optics.TaylorTerms;
import diffract.optics.TermFormat;
import diffract.optics.Variant;
import diffract.util.Reporter;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Baked tables cached in memory per (patch terms, settings), so a viewer or a benchmark that draws the same patch
 * again never bakes twice. Terms are compared by identity (they are immutable); settings by value, with the
 * variant, the term format and the Fresnel model ignored (the table is FLSS's or the lobes method's on float32
 * terms whatever variant asks, before the gain factor). The least recently used table is dropped beyond
 * {@link #MAX_TABLES}: a table can take hundreds of MB. Thread-safe.
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
            return System.identityHashCode(terms) * 31 + settings.hashCode() * 7 + Boolean.hashCode(lobes);
        }
    }

    private static final Map<Key, BakedTable> CACHE = new LinkedHashMap<>(4, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Key, BakedTable> eldest) {
            return size() > MAX_TABLES;
        }
    };
    private static int bakes;

    private BakedTables() {
    }

    /**
     * The table of these terms and settings, baked on the first request: of the lobes method, cell- and
     * light-averaged, when the illumination filters (a pixel box or a light) and the lobes shader can take the patch
     * (no texel pairs); else of FLSS.
     */
    public static synchronized BakedTable of(TaylorTerms terms, BrdfSettings settings, Reporter reporter) {
        boolean lobes = bakesLobes(terms, settings);
        Key key = new Key(terms, settings.with(b -> b.variant(Variant.BAKED).termFormat(TermFormat.RG32F)
                .fresnel(FresnelModel.PHYSICAL)), lobes);
        BakedTable table = CACHE.get(key);
        if (table == null) {
            table = bakeOffThisThread(terms, settings, lobes, reporter);
            CACHE.put(key, table);
            bakes++;
        }
        return table;
    }

    /** Whether {@link #of} bakes the lobes method (else FLSS). */
    static boolean bakesLobes(TaylorTerms terms, BrdfSettings settings) {
        if (!settings.illumination().filters()) {
            return false;
        }
        CoherenceWindow window = settings.coherenceWindow();
        double threshold = settings.lobes().pairThreshold();
        return LobeQuadrature.pairRadius(window.sigmaTexels(terms.cols() * terms.pixelSizeXUm()), threshold) == 0
                && LobeQuadrature.pairRadius(window.sigmaTexels(terms.rows() * terms.pixelSizeYUm()), threshold) == 0;
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
        } catch (java.util.concurrent.CompletionException e) {
            throw e.getCause() instanceof RuntimeException r ? r : e;
        }
    }

    /** How many tables were baked so far (tests: the cache bakes once). */
    public static synchronized int bakeCount() {
        return bakes;
    }
}
