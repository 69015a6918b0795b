package diffract.app;

import diffract.app.jobs.Sbatch;
import diffract.app.jobs.SlurmOptions;
import diffract.app.jobs.SlurmScript;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** What submit hands its workers or writes into a Slurm job script, and what it refuses before starting any. */
class SubmitCommandTest {
    @TempDir
    Path dir;

    static final List<String> MAP = List.of("brdfmap", "--synthetic", "blazed", "--theta-i", "30", "--size", "16");

    @Test
    void workersGetTheOptionsLessTheOutputsMergeWrites() {
        assertEquals(List.of("--synthetic", "blazed", "--theta-i", "30", "--size", "24"),
                SubmitCommand.withoutOutputs(List.of("--synthetic", "blazed", "-o", "m.png", "--theta-i", "30",
                        "--pfm=m.pfm", "--exr", "m.exr", "--size", "24", "--output=x.png", "-oy.png")));
    }

    @Test
    void aMapsOuterBandsAreHandedOutFirstAndEveryOtherCommandsPiecesInOrder() {
        BrdfMapCommand map = new BrdfMapCommand();
        assertArrayEquals(new int[] {0, 7, 1, 6, 2, 5, 3, 4}, map.dispatchOrder(8));
        assertArrayEquals(new int[] {0, 4, 1, 3, 2}, map.dispatchOrder(5));
        assertArrayEquals(new int[] {0}, map.dispatchOrder(1));
        assertArrayEquals(new int[] {0, 1, 2, 3}, new RenderCommand().dispatchOrder(4));
    }

    @Test
    void aCommandThatDoesNotSplitIsRefused() {
        Object[] result = CliTest.run("submit", "--local", "2", "--", "measure", "assets/scenes/snake-elaphe.json");
        assertEquals(2, result[0]);
        assertTrue(((String) result[2]).contains(
                "submit runs brdfmap, render --turntable or bench in pieces, not measure"),
                (String) result[2]);
        result = CliTest.run("submit", "--local", "2", "--", "render", "assets/scenes/blazed-grating-plane.json", "-o",
                "x.png");
        assertEquals(2, result[0]);
        assertTrue(((String) result[2]).contains("add --turntable FRAMES"), (String) result[2]);
        result = CliTest.run("submit", "--local", "2", "--piece-count", "5", "--", "render",
                "assets/scenes/blazed-grating-plane.json", "--turntable", "4", "-o", "x.gif");
        assertEquals(2, result[0]);
        assertTrue(((String) result[2]).contains("has only 4 frames to split"), (String) result[2]);
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

    @Test
    void theJobScriptAsksForWhatTheOptionsSayAndRunsOnePieceATask() {
        SlurmOptions slurm = new SlurmOptions();
        slurm.slurm = true;
        slurm.maxRunning = 3;
        slurm.cpusPerTask = 4;
        slurm.gpusPerTask = 1;
        slurm.cacheDir = Path.of("/shared/cache");
        slurm.partition = "gpu";
        slurm.timeLimit = "0:30:00";
        slurm.sbatchOptions = List.of("--account=lab");
        String script = SlurmScript.text(slurm, "brdfmap", List.of("--synthetic", "blazed", "--theta-i", "30"),
                Path.of("/shared/my pieces"), 8, Path.of("/home/u"), List.of("/opt/java/bin/java", "-Xmx4g"),
                List.of("-cp", "/opt/d.jar", "diffract.app.Main"), List.of("diffract", "merge", "/shared/my pieces",
                        "-o", "/home/u/map.png"));
        List<String> lines = script.lines().toList();
        assertEquals("#!/bin/bash", lines.get(0));
        for (String line : List.of("#SBATCH --array=0-7%3", "#SBATCH --cpus-per-task=4", "#SBATCH --gres=gpu:1",
                "#SBATCH --partition=gpu", "#SBATCH --time=0:30:00", "#SBATCH --account=lab",
                "#SBATCH --chdir=/home/u", "#SBATCH --output=\"/shared/my pieces/piece-%a-of-8.log\"",
                "export DIFFRACT_CACHE=/shared/cache", "unset DISPLAY", "export DIFFRACT_GL=egl",
                "# once every piece is there: diffract merge '/shared/my pieces' -o /home/u/map.png")) {
            assertTrue(lines.contains(line), line + " missing from\n" + script);
        }
        String exec = lines.get(lines.size() - 1);
        assertEquals("exec /opt/java/bin/java -Xmx4g -Djava.awt.headless=true "
                + "\"-XX:ActiveProcessorCount=${SLURM_CPUS_PER_TASK:-4}\" -cp /opt/d.jar diffract.app.Main brdfmap "
                + "--synthetic blazed --theta-i 30 --tile \"${SLURM_ARRAY_TASK_ID}/8\" --pieces '/shared/my pieces'",
                exec);
        // every #SBATCH line comes before the first command: sbatch reads no further
        int firstCommand = lines.indexOf("set -euo pipefail");
        assertTrue(lines.subList(firstCommand, lines.size()).stream().noneMatch(l -> l.startsWith("#SBATCH")));
    }

    @Test
    void withoutGpusOrCacheTheScriptLeavesTheNodesDefaults() {
        SlurmOptions slurm = new SlurmOptions();
        slurm.slurm = true;
        String script = SlurmScript.text(slurm, "brdfmap", List.of("--size", "16"), Path.of("/p"), 2, Path.of("/w"),
                List.of("java"), List.of("-cp", "x", "M"), List.of("diffract", "merge", "/p", "-o", "/w/m.png"));
        assertTrue(script.contains("#SBATCH --array=0-1\n"), script);
        assertTrue(script.contains("#SBATCH --cpus-per-task=1\n"), script);
        for (String absent : List.of("--gres", "DIFFRACT_CACHE", "DIFFRACT_GL", "--partition", "--time")) {
            assertFalse(script.contains(absent), absent + " in\n" + script);
        }
    }

    @Test
    void wordsTheShellWouldSplitOrExpandAreQuoted() {
        assertEquals("plain/path-1.png", SlurmScript.quote("plain/path-1.png"));
        assertEquals("'a b'", SlurmScript.quote("a b"));
        assertEquals("'$HOME'", SlurmScript.quote("$HOME"));
        assertEquals("'it'\\''s'", SlurmScript.quote("it's"));
        assertEquals("''", SlurmScript.quote(""));
    }

    @Test
    void localWorkersTakeTheProcessorsTheyAreGivenAndNoFewerThanOne() {
        Object[] none = CliTest.run("submit", "--local", "2", "--cpus-per-task", "0", "--", "brdfmap",
                "--synthetic", "blazed", "--theta-i", "30", "--size", "16", "-o", dir.resolve("x.png").toString());
        assertEquals(2, none[0]);
        assertTrue(((String) none[2]).contains("--cpus-per-task must be at least 1"), (String) none[2]);
    }

    @Test
    void slurmRefusesWhatItCannotRunInOneLine() {
        List<String[]> refused = List.of(
                args(List.of("submit", "--slurm", "--keep-pieces", dir.toString())),
                args(List.of("submit", "--slurm", "--piece-count", "2")),
                args(List.of("submit", "--local", "2", "--max-running", "2", "--gpus-per-task", "2")),
                args(List.of("submit", "--local", "2", "--slurm", "--piece-count", "2", "--keep-pieces",
                        dir.toString())),
                args(List.of("submit", "--piece-count", "2")),
                args(List.of("submit", "--slurm", "--piece-count", "2", "--keep-pieces", dir.toString(),
                        "--max-running", "0")),
                args(List.of("submit", "--slurm", "--piece-count", "2", "--keep-pieces", dir.toString(),
                        "--partition", "a b")),
                args(List.of("submit", "--slurm", "--piece-count", "2", "--keep-pieces", dir.toString(),
                        "--sbatch-option", "account=lab")));
        List<String> expected = List.of("--slurm needs --piece-count N", "--slurm needs --keep-pieces DIR",
                "--max-running, --gpus-per-task go with --slurm", "--local and --slurm exclude each other",
                "submit needs --local J (worker processes here) or --slurm", "--max-running must be at least 1",
                "--partition takes one word", "--sbatch-option takes one sbatch option as --name=value");
        for (int i = 0; i < refused.size(); i++) {
            Object[] result = CliTest.run(refused.get(i));
            assertEquals(2, result[0], String.join(" ", refused.get(i)));
            String err = (String) result[2];
            assertEquals(1, err.lines().count(), err);
            assertTrue(err.startsWith("diffract: " + expected.get(i)), err);
        }
    }

    /** Where sbatch is not installed, one line says so, and the job script is there to take elsewhere. */
    @Test
    void withoutSbatchSubmitSaysSoInOneLine() {
        String program = Sbatch.program;
        Sbatch.program = "diffract-test-no-such-sbatch";
        try {
            Path pieces = dir.resolve("pieces");
            Object[] result = CliTest.run(args(List.of("submit", "--slurm", "--piece-count", "2", "--keep-pieces",
                    pieces.toString(), "--", "brdfmap", "--synthetic", "blazed", "--theta-i", "30", "--size", "16",
                    "-o", dir.resolve("m.png").toString())));
            assertEquals(2, result[0]);
            assertEquals("diffract: diffract-test-no-such-sbatch not found: --slurm submits with Slurm's sbatch, on a "
                    + "machine that can submit jobs (a cluster's login node); or run the pieces here with --local J",
                    ((String) result[2]).strip());
            assertTrue(Files.isRegularFile(pieces.resolve("job.sbatch")));
        } finally {
            Sbatch.program = program;
        }
    }

    private static String[] args(List<String> submit) {
        List<String> all = new java.util.ArrayList<>(submit);
        if (!all.contains("--")) {
            all.add("--");
            all.addAll(MAP);
            all.addAll(List.of("-o", "m.png"));
        }
        return all.toArray(String[]::new);
    }
}
