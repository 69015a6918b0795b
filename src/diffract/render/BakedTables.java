package diffract.render;

import diffract.optics.BrdfSettings;
import diffract.optics.TaylorTerms;
import diffract.optics.Variant;
import diffract.util.Reporter;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Baked tables cached in memory per (patch terms, settings), so a viewer or a benchmark that draws the same patch
 * again never bakes twice. Terms are compared by identity (they are immutable); settings by value, with the
 * variant ignored (the table is FLSS's whatever variant asks). The least recently used table is dropped beyond
 * {@link #MAX_TABLES}: a table can take hundreds of MB. Thread-safe.
 */
public final class BakedTables {
    /** Tables kept at once. */
    public static final int MAX_TABLES = 2;

    private record Key(TaylorTerms terms, BrdfSettings settings) {
        @Override
        public boolean equals(Object o) {
            return o instanceof Key k && k.terms == terms && k.settings.equals(settings);
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
    private static int bakes;

    private BakedTables() {
    }

    /** The table of these terms and settings, baked on the first request. */
    public static synchronized BakedTable of(TaylorTerms terms, BrdfSettings settings, Reporter reporter) {
        Key key = new Key(terms, settings.withVariant(Variant.BAKED));
        BakedTable table = CACHE.get(key);
        if (table == null) {
            table = BakedTable.bake(terms, settings, BakedTable.PRECISION, reporter);
            CACHE.put(key, table);
            bakes++;
        }
        return table;
    }

    /** How many tables were baked so far (tests: the cache bakes once). */
    public static synchronized int bakeCount() {
        return bakes;
    }
}
