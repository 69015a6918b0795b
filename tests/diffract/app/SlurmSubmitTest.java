package diffract.app;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

/**
 * {@code submit --slurm} on a real Slurm: the one-node cluster that {@code .ci/slurm-node} starts on this machine
 * (its controller and node here, so a temporary folder is a folder every node shares). A 4-task array of a 64^2
 * reference map merges into the single run's files bit for bit; a job the scheduler refuses, tasks that die and
 * {@code --no-wait} each end as they say. Tagged {@value #SLURM_TAG}: the default run leaves it out (pom.xml's
 * {@code diffract.excludedGroups}); {@code .ci/run} selects it after starting the node, and where no Slurm answers
 * the test fails, saying how to start one, rather than passing unseen.
 */
@Tag(SlurmSubmitTest.SLURM_TAG)
class SlurmSubmitTest {
    /** JUnit tag of the tests that need a running Slurm (.ci/slurm-node). */
    static final String SLURM_TAG = "slurm";

    @TempDir
    static Path dir;

    /** A 64^2 reference map of a blazed grating at a short coherence length: seconds per piece on one core. */
    static final List<String> MAP = List.of("brdfmap", "--synthetic", "blazed", "--coherence-length", "10",
            "--theta-i", "30", "--size", "64", "--exposure", "auto", "--variant", "reference");

    @BeforeAll
    static void aSlurmNodeAnswers() throws InterruptedException {
        String states;
        try {
            Process p = new ProcessBuilder("sinfo", "-h", "-o", "%T").redirectErrorStream(true).start();
            states = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
            if (p.waitFor() != 0) {
                fail("sinfo fails (" + states + "): the tests tagged " + SLURM_TAG + " need a running one-node "
                        + "Slurm: bash .ci/slurm-node (as root)");
            }
        } catch (IOException e) {
            fail("sinfo not found: the tests tagged " + SLURM_TAG + " need Slurm (bash .ci/install-deps --tests "
                    + "installs slurm-wlm and munge) running on this machine (bash .ci/slurm-node, as root)");
            return;
        }
        if (!states.lines().anyMatch(s -> s.equals("idle") || s.equals("mixed") || s.equals("allocated"))) {
            fail("no Slurm node is up (sinfo shows '" + states + "'): bash .ci/slurm-node (as root)");
        }
    }

    @Test
    void fourTasksOfAnArrayMergeIntoTheSingleRunsFilesBitForBit() throws IOException {
        Path wholePng = dir.resolve("whole.png");
        Path wholePfm = dir.resolve("whole.pfm");
        ok(CliTest.run(map(wholePng, wholePfm)));

        Path pieces = dir.resolve("pieces");
        Path png = dir.resolve("merged.png");
        Path pfm = dir.resolve("merged.pfm");
        List<String> submit = new ArrayList<>(List.of("submit", "--slurm", "--piece-count", "4", "--keep-pieces",
                pieces.toString(), "--max-running", "2", "--cpus-per-task", "1", "--cache-dir",
                dir.resolve("cache").toString(), "--"));
        submit.addAll(List.of(map(png, pfm)));
        Object[] result = ok(CliTest.run(submit.toArray(String[]::new)));
        String out = (String) result[1];
        assertTrue(out.contains("as Slurm array job ") && out.contains(": 4 pieces of 64 rows, at most 2 at once"),
                out);
        assertTrue(out.contains("wrote " + png + " from 4 pieces of Slurm array job"), out);

        assertEquals(-1, Files.mismatch(wholePfm, pfm), "PFM floats differ");
        assertEquals(-1, Files.mismatch(wholePng, png), "PNG bytes differ");
        // each task computed its own band, as its log says
        for (int i = 0; i < 4; i++) {
            String log = Files.readString(pieces.resolve("piece-" + i + "-of-4.log"));
            assertTrue(log.contains("wrote piece " + i + "/4 (rows " + 16 * i + ".." + (16 * i + 15) + " of 64)"), log);
        }
        String script = Files.readString(pieces.resolve("job.sbatch"));
        assertTrue(script.contains("#SBATCH --array=0-3%2\n"), script);
        // negative control: the bands differ, so one merged in the wrong place would show in the files
        assertTrue(Files.mismatch(pieces.resolve("piece-0-of-4.f32"), pieces.resolve("piece-1-of-4.f32")) >= 0);
    }

    @Test
    void aJobTheSchedulerRefusesIsOneLine() {
        Path pieces = dir.resolve("refused");
        Object[] result = CliTest.run(submit(pieces, "--partition", "no-such-partition"));
        assertEquals(2, result[0], (String) result[2]);
        String err = ((String) result[2]).strip();
        assertEquals(1, err.lines().count(), err);
        assertTrue(err.startsWith("diffract: sbatch did not accept " + pieces.resolve("job.sbatch") + " (exit code 1): "
                + "sbatch: error: Batch job submission failed: Invalid partition name specified"), err);
    }

    /** Tasks that die (here: Java refuses an option) leave their pieces missing; one line names them and the logs. */
    @Test
    void piecesTheArrayDidNotWriteAreNamedWithTheirLogs() {
        Path pieces = dir.resolve("dying");
        Object[] result = CliTest.run(submit(pieces, "--sbatch-option=--export=ALL,JAVA_TOOL_OPTIONS=-XX:+NoSuchFlag"));
        assertEquals(2, result[0], (String) result[2]);
        String err = ((String) result[2]).strip();
        assertEquals(1, err.lines().count(), err);
        assertTrue(err.matches("diffract: Slurm array job [0-9]+ ended without pieces 0, 1 of 2 \\(see "
                + Pattern.quote(pieces.resolve("piece-0-of-2.log").toString()) + "\\); resubmit them with sbatch "
                + "--array=0,1 " + Pattern.quote(pieces.resolve("job.sbatch").toString()) + ", then diffract merge "
                + ".*"), err);
    }

    /** A held job (sbatch --hold) is accepted and never runs: submit returns with the merge command to run later. */
    @Test
    void withNoWaitSubmitReturnsWithTheMergeCommand() throws Exception {
        Path pieces = dir.resolve("held");
        Object[] result = ok(CliTest.run(submit(pieces, "--no-wait", "--sbatch-option=--hold")));
        String out = (String) result[1];
        Matcher id = Pattern.compile("as Slurm array job ([0-9]+):").matcher(out);
        assertTrue(id.find(), out);
        try {
            assertTrue(out.contains("once the array has ended: diffract merge " + pieces + " -o "
                    + Path.of("m.png").toAbsolutePath()), out);
            assertFalse(Files.exists(pieces.resolve("piece-0-of-2.json")));
        } finally {
            new ProcessBuilder("scancel", id.group(1)).inheritIO().start().waitFor();
        }
    }

    private static String[] submit(Path pieces, String... slurm) {
        List<String> args = new ArrayList<>(List.of("submit", "--slurm", "--piece-count", "2", "--keep-pieces",
                pieces.toString()));
        args.addAll(List.of(slurm));
        args.add("--");
        args.addAll(List.of("brdfmap", "--synthetic", "blazed", "--theta-i", "30", "--size", "16", "-o", "m.png"));
        return args.toArray(String[]::new);
    }

    private static String[] map(Path png, Path pfm) {
        List<String> args = new ArrayList<>(MAP);
        args.addAll(List.of("-o", png.toString(), "--pfm", pfm.toString()));
        return args.toArray(String[]::new);
    }

    private static Object[] ok(Object[] result) {
        assertEquals(0, result[0], (String) result[2]);
        return result;
    }
}
