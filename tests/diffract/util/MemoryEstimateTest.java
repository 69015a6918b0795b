package diffract.util;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The memory refusal's arithmetic and words; the folder lock's reentrancy and its clean-up of leftovers. */
class MemoryEstimateTest {
    @Test
    void aFittingEstimatePassesAndALargerOneIsRefusedWithItsPartsAndAHeapSuggestion() {
        MemoryEstimate e = MemoryEstimate.of("terms", 3_000_000_000L).plus("map", 12_000_000L).plus("none", 0);
        assertEquals(3_012_000_000L, e.bytes());
        assertEquals(2, e.parts().size(), "a part of 0 bytes is left out");
        e.require("work", "do less", 4_000_000_000L, 4_000_000_000L);
        UserInputException refused = assertThrows(UserInputException.class,
                () -> e.require("the work", "do less", 1_000_000_000L, 2_000_000_000L));
        // 3.012e9 * 1.25 / 2^30 = 3.51 GiB; plus half a GiB of margin, rounded up: 5
        assertEquals("the work needs about 3.0 GB of memory (terms 3.0 GB + map 12 MB), but the Java heap can grow"
                + " by only 1.0 GB (limit 2.0 GB); do less, or give Java a larger heap: DIFFRACT_JAVA_OPTS=-Xmx5g"
                + " ./diffract ... (java -Xmx5g -jar ...)", refused.getMessage());
        assertEquals("5.0 TB", MemoryEstimate.size(5_000_000_000_000L));
        assertEquals(Long.MAX_VALUE, MemoryEstimate.of("a", Long.MAX_VALUE).plus("b", 5).bytes(), "saturates");
    }

    @TempDir
    Path dir;

    @Test
    void theFolderLockIsReentrantAndRemovesLeftoversOnly() throws Exception {
        Files.writeString(dir.resolve("terms.f32.tmp-1-2"), "x");
        Files.writeString(dir.resolve("terms.f32"), "kept");
        try (FolderLock outer = FolderLock.acquire(dir, Reporter.SILENT);
             FolderLock inner = FolderLock.acquire(dir, Reporter.SILENT)) {
            assertEquals(1, inner.removeStaleTemporaries());
            assertEquals(0, outer.removeStaleTemporaries());
        }
        assertTrue(Files.isRegularFile(dir.resolve("terms.f32")));
        try (FolderLock again = FolderLock.acquire(dir, Reporter.SILENT)) {
            assertEquals(0, again.removeStaleTemporaries(), "released and taken again");
        }
    }
}
