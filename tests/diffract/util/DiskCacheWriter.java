package diffract.util;

import java.nio.file.Path;

/**
 * A second process for {@link DiskCacheTest}: stores the same entry as the test's other writers, again and again, and
 * checks every entry it loads back.
 */
public final class DiskCacheWriter {
    private DiskCacheWriter() {
    }

    /** Arguments: the cache folder and how many times to store. Exits 0 when every load read a whole entry. */
    public static void main(String[] args) {
        DiskCache cache = DiskCache.at(Path.of(args[0]), Long.MAX_VALUE, java.time.Clock.systemUTC());
        int times = Integer.parseInt(args[1]);
        for (int i = 0; i < times; i++) {
            cache.store(DiskCacheTest.SHARED_KEY, out -> DiskCache.writeFloats(out, DiskCacheTest.sharedPayload()),
                    "the shared entry", Reporter.SILENT);
            float[] back = cache.load(DiskCacheTest.SHARED_KEY, DiskCacheTest::readShared, Reporter.SILENT, "again");
            if (back == null || !java.util.Arrays.equals(back, DiskCacheTest.sharedPayload())) {
                System.exit(1);
            }
        }
        System.exit(0);
    }
}
