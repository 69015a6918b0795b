package diffract.app;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Worker processes run the commands they are handed one after another, each command's output and exit code its own;
 * the first failure stops them.
 */
class LocalWorkersTest {
    @Test
    void oneWorkerRunsEveryCommandWithItsOwnOutput() throws Exception {
        List<List<String>> commands = List.of(List.of("--version"), List.of("merge", "--help"), List.of("--version"));
        List<LocalWorkers.Finished> done = Collections.synchronizedList(new ArrayList<>());
        assertNull(LocalWorkers.run(commands, 1, 1, done::add));
        assertEquals(List.of(0, 1, 2), done.stream().map(LocalWorkers.Finished::index).toList());
        assertEquals("diffract 0.1.0\n", done.get(0).output());
        assertTrue(done.get(1).output().startsWith("Usage: diffract merge"), done.get(1).output());
        assertEquals("diffract 0.1.0\n", done.get(2).output());
        assertTrue(done.stream().allMatch(f -> f.exitCode() == 0 && f.wallS() > 0));
    }

    @Test
    void workersTakeTheCommandsInTheOrderGivenAndReportTheirOwnIndices() throws Exception {
        List<List<String>> commands = List.of(List.of("--version"), List.of("merge", "--help"), List.of("--version"));
        List<LocalWorkers.Finished> done = Collections.synchronizedList(new ArrayList<>());
        assertNull(LocalWorkers.run(commands, new int[] {2, 0, 1}, 1, 1, done::add));
        assertEquals(List.of(2, 0, 1), done.stream().map(LocalWorkers.Finished::index).toList());
        assertTrue(done.get(2).output().startsWith("Usage: diffract merge"), done.get(2).output());
        assertThrows(IllegalArgumentException.class,
                () -> LocalWorkers.run(commands, new int[] {0, 0, 1}, 1, 1, done::add), "each once");
        assertThrows(IllegalArgumentException.class,
                () -> LocalWorkers.run(commands, new int[] {0, 1}, 1, 1, done::add), "every one");
    }

    @Test
    void theFirstFailureStopsTheWorkersAndIsReturned() throws Exception {
        List<List<String>> commands = List.of(List.of("--version"), List.of("merge", "/no/such/pieces", "-o", "x.png"),
                List.of("--version"), List.of("--version"), List.of("--version"));
        List<LocalWorkers.Finished> done = Collections.synchronizedList(new ArrayList<>());
        LocalWorkers.Finished failed = LocalWorkers.run(commands, 1, 1, done::add);
        assertNotNull(failed);
        assertEquals(1, failed.index());
        assertEquals(2, failed.exitCode());
        assertTrue(failed.output().contains("merge: /no/such/pieces is not a folder of pieces"), failed.output());
        assertEquals(List.of(0, 1), done.stream().map(LocalWorkers.Finished::index).toList(), "none after it");
    }
}
