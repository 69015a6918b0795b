package diffract.util;

import java.nio.file.Path;

/**
 * Points the disk cache ({@link DiskCache#ROOT_PROPERTY}) at a folder of a test for as long as it is open, then back
 * at what it was (the build's test cache, never the user's): tests that count bakes or entries need a cache of their
 * own, empty at the start.
 */
public final class TestCache implements AutoCloseable {
    private final String before;

    private TestCache(String before) {
        this.before = before;
    }

    /** Uses {@code dir} as the disk cache until {@link #close}. */
    public static TestCache at(Path dir) {
        TestCache cache = new TestCache(System.getProperty(DiskCache.ROOT_PROPERTY));
        System.setProperty(DiskCache.ROOT_PROPERTY, dir.toString());
        DiskCache.useDisk(true);
        return cache;
    }

    @Override
    public void close() {
        if (before == null) {
            System.clearProperty(DiskCache.ROOT_PROPERTY);
        } else {
            System.setProperty(DiskCache.ROOT_PROPERTY, before);
        }
    }
}
