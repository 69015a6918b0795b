package diffract.util;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/** Special files for the tests of outputs that must never be replaced. */
public final class SpecialFiles {
    private SpecialFiles() {
    }

    /** A named pipe made by mkfifo (in a folder made first); skips where there is none (not Linux). */
    public static Path fifo(Path where) throws IOException, InterruptedException {
        Files.createDirectories(where.getParent());
        Process p;
        try {
            p = new ProcessBuilder("mkfifo", where.toString()).redirectErrorStream(true).start();
        } catch (IOException e) {
            assumeTrue(false, "no mkfifo here");
            throw e;
        }
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(0, p.waitFor(), output);
        assertEquals("a named pipe (fifo)", OutputPaths.kind(where));
        return where;
    }
}
