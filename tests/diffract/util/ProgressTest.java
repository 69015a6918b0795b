package diffract.util;

import org.junit.jupiter.api.Test;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Optional;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The progress rule with a clock the test moves: silent short work, throttled lines, a linear time left. */
class ProgressTest {
    private static final long S = 1_000_000_000L;

    @Test
    void workShorterThanTwoSecondsPrintsNothing() {
        Progress p = new Progress("map", 0);
        for (int i = 0; i <= 10; i++) {
            assertEquals(Optional.empty(), p.update(i / 10.0, (long) (0.19 * i * S)), "step " + i);
        }
        assertTrue(p.finished());
    }

    @Test
    void longWorkPrintsAtMostEveryFiveSecondsWithTheTimeLeftAndEndsWithDone() {
        Progress p = new Progress("bake", 0);
        p.update(0, 0);
        assertEquals(Optional.empty(), p.update(0.05, S)); // 1 s: too early
        // 2.5 s for 10 %: the rate says 22.5 s are left
        assertEquals(Optional.of("bake: 10 % after 3 s, about 23 s left"), p.update(0.10, (long) (2.5 * S)));
        assertEquals(Optional.empty(), p.update(0.20, 5 * S)); // 2.5 s after the last line
        assertEquals(Optional.of("bake: 30 % after 8 s, about 18 s left"), p.update(0.30, (long) (7.5 * S)));
        assertEquals(Optional.of("bake: done in 25 s"), p.update(1.0, 25 * S));
        assertEquals(Optional.empty(), p.update(1.0, 26 * S), "once");
    }

    @Test
    void theRateLeavesOutTheWorkBeforeTheFirstReport() {
        Progress p = new Progress("precompute", 0);
        p.update(0.5, 0); // the first report comes at half-way: its clock starts here
        assertEquals(Optional.of("precompute: 75 % after 3 s, about 3 s left"), p.update(0.75, 3 * S));
    }

    @Test
    void durationsReadAsMinutesAndHours() {
        assertEquals("59 s", Progress.duration(59.4));
        assertEquals("2 min 05 s", Progress.duration(125));
        assertEquals("1 h 02 min", Progress.duration(3720));
    }

    /** The console reporter: per task, warnings always, notes and progress not when quiet. */
    @Test
    void consoleReporterThrottlesPerTaskAndQuietKeepsOnlyWarnings() {
        long[] now = {0};
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream stream = new PrintStream(bytes, true, StandardCharsets.UTF_8);
        ConsoleReporter loud = new ConsoleReporter(false, () -> now[0], () -> stream);
        loud.progress("a", 0);
        now[0] = 3 * S;
        loud.progress("a", 0.5);
        loud.progress("b", 0.1); // b starts now: silent
        now[0] = 6 * S;
        loud.progress("a", 1.0);
        loud.progress("b", 1.0);
        loud.info("note");
        loud.warn("careful");
        assertEquals(List.of("a: 50 % after 3 s, about 3 s left", "a: done in 6 s", "note", "warning: careful"),
                bytes.toString(StandardCharsets.UTF_8).lines().toList());

        bytes.reset();
        ConsoleReporter quiet = new ConsoleReporter(true, () -> now[0], () -> stream);
        quiet.progress("c", 0);
        now[0] = 60 * S;
        quiet.progress("c", 0.5);
        quiet.info("note");
        quiet.warn("careful");
        assertEquals(List.of("warning: careful"), bytes.toString(StandardCharsets.UTF_8).lines().toList());
    }
}
