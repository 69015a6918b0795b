package diffract.app;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** What submit hands its workers, and what it refuses before starting any. */
class SubmitCommandTest {
    @Test
    void workersGetTheOptionsLessTheOutputsMergeWrites() {
        assertEquals(List.of("--synthetic", "blazed", "--theta-i", "30", "--size", "24"),
                SubmitCommand.withoutOutputs(List.of("--synthetic", "blazed", "-o", "m.png", "--theta-i", "30",
                        "--pfm=m.pfm", "--exr", "m.exr", "--size", "24", "--output=x.png", "-oy.png")));
    }

    @Test
    void aCommandOtherThanBrdfmapIsRefused() {
        Object[] result = CliTest.run("submit", "--local", "2", "--", "render", "-o", "x.png");
        assertEquals(2, result[0]);
        assertTrue(((String) result[2]).contains("submit runs brdfmap"), (String) result[2]);
    }

    @Test
    void aGpuMapOrMorePiecesThanRowsAreRefusedBeforeAnyWorkerStarts() {
        Object[] gpu = CliTest.run("submit", "--local", "2", "--", "brdfmap", "--synthetic", "blazed", "--theta-i",
                "30", "--variant", "flss", "--engine", "gpu", "-o", "x.png");
        assertEquals(2, gpu[0]);
        assertTrue(((String) gpu[2]).contains("splits the CPU's work"), (String) gpu[2]);
        Object[] rows = CliTest.run("submit", "--local", "2", "--piece-count", "17", "--", "brdfmap", "--synthetic",
                "blazed", "--theta-i", "30", "--size", "16", "-o", "x.png");
        assertEquals(2, rows[0]);
        assertTrue(((String) rows[2]).contains("has only 16 rows"), (String) rows[2]);
        Object[] missing = CliTest.run("submit", "--local", "2", "--", "brdfmap", "--synthetic", "blazed",
                "--theta-i", "30");
        assertEquals(2, missing[0]);
        assertTrue(((String) missing[2]).contains("needs -o"), (String) missing[2]);
    }
}
