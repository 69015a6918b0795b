package diffract.app;

import diffract.bench.ReferenceMaps;
import diffract.bench.ResultsTable;
import diffract.jrtr.GlTestSupport;
import diffract.util.DiskCache;
import diffract.util.TestCache;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** {@code diffract bench} on a tiny sweep: the files, the CSV's columns and one row per configuration. */
class BenchCommandTest {
    @Test
    void aTinySweepWritesOneCsvRowPerConfigurationAndThePlot(@TempDir Path dir) throws Exception {
        GlTestSupport.assumeOffscreenGl();
        Path out = dir.resolve("bench");
        int code;
        try (TestCache ignored = TestCache.at(dir.resolve("cache"))) { // empty: its reference maps are counted
            // flss: 2 orders x 2 formats = 4; nmm ignores the step, same 4; 24 px maps keep it to seconds
            code = Main.execute("bench", "--patches", "blazed", "--variants", "flss,nmm", "--terms", "4,8",
                    "--lambda-steps", "25", "--window-radii", "1", "--texture-formats", "rg32f,rg8", "--size", "24",
                    "-o", out.toString());
        }
        assertEquals(0, code);
        List<String> lines = Files.readAllLines(out.resolve("results.csv"));
        List<String> required = List.of("variant", "patch", "terms", "lambda_step_nm", "window_radius",
                "texture_format", "width", "height", "ms_per_frame", "deltaE_mean", "deltaE_p95");
        List<String> header = List.of(lines.get(0).split(","));
        assertTrue(header.containsAll(required), "header " + header);
        assertEquals(ResultsTable.COLUMNS, header);
        assertEquals(1 + 8, lines.size(), String.join("\n", lines));
        for (String line : lines.subList(1, lines.size())) {
            String[] f = line.split(",", -1);
            assertEquals(header.size(), f.length, line);
            assertEquals("blazed", f[header.indexOf("patch")]);
            assertEquals("24", f[header.indexOf("width")]);
            assertFalse(f[header.indexOf("gl_renderer")].isBlank(), "the renderer is recorded: " + line);
            assertFalse(f[header.indexOf("gl_version")].isBlank(), line);
            double ms = Double.parseDouble(f[header.indexOf("ms_per_frame")]);
            double mean = Double.parseDouble(f[header.indexOf("deltaE_mean")]);
            double p95 = Double.parseDouble(f[header.indexOf("deltaE_p95")]);
            assertTrue(ms > 0 && mean >= 0 && p95 >= 0 && Double.isFinite(mean), line);
        }
        assertEquals(4, lines.stream().filter(l -> l.startsWith("nmm,")).count());
        assertEquals(2, lines.stream().filter(l -> l.contains(",rg8,")).filter(l -> l.startsWith("flss,")).count());
        assertTrue(Files.size(out.resolve("pareto.png")) > 1000);
        assertTrue(Files.readString(out.resolve("pareto.md")).contains("**yes**"));
        assertTrue(Files.readString(out.resolve("results.md")).contains("| blazed | flss | 8 | 25 | 1 | 0 | rg8 | 24 |"));
        assertTrue(Files.readString(out.resolve("machine.txt")).contains("CPU cores"));
        try (Stream<Path> maps = Files.list(dir.resolve("cache").resolve(ReferenceMaps.KIND))) {
            assertEquals(3, maps.filter(p -> p.toString().endsWith(DiskCache.ENTRY_SUFFIX)).count(),
                    "one reference map per light in the disk cache");
        }
        assertFalse(Files.exists(out.resolve("reference-maps")), "none in the output folder");
    }

    /** --variant auto needs its target, and the target needs auto: one line, exit code 2, before any work. */
    @Test
    void autoAndItsTargetComeTogether(@TempDir Path dir) {
        String patch = dir.resolve("none.gsf").toString(); // never read: the options are checked first
        Object[] noTarget = CliTest.run("brdfmap", "--patch", patch, "--theta-i", "10", "--variant", "auto",
                "-o", dir.resolve("a.png").toString());
        assertEquals(2, noTarget[0]);
        assertTrue(((String) noTarget[2]).contains("--max-delta-e"), (String) noTarget[2]);
        Object[] noAuto = CliTest.run("brdfmap", "--patch", patch, "--theta-i", "10", "--variant", "flss",
                "--max-delta-e", "2", "-o", dir.resolve("a.png").toString());
        assertEquals(2, noAuto[0]);
        assertTrue(((String) noAuto[2]).contains("--variant auto"), (String) noAuto[2]);
    }

    @Test
    void refusesTheReferenceAndUnknownFormatsWithExitCode2(@TempDir Path dir) {
        assertEquals(2, Main.execute("bench", "--variants", "reference", "-o", dir.toString()));
        assertEquals(2, Main.execute("bench", "--texture-formats", "rg4", "-o", dir.toString()));
        assertEquals(2, Main.execute("bench", "--quick", "--terms", "8", "-o", dir.toString()));
    }

    /**
     * --filtering's extra patch is read as every command reads one, and only --filtering takes it (the GPU suite
     * refuses it, and --filtering beside it).
     */
    @Test
    void anExtraPatchNeedsFilteringAndIsCheckedAsEveryCommandChecksIt(@TempDir Path dir) {
        Object[] noFiltering = CliTest.run("bench", "--synthetic", "blazed-10um", "-o", dir.toString());
        assertEquals(2, noFiltering[0]);
        assertTrue(((String) noFiltering[2]).contains("add --filtering"), (String) noFiltering[2]);
        Object[] suite = CliTest.run("bench", "--gpu-suite", "--synthetic", "blazed-10um", "-o", dir.toString());
        assertEquals(2, suite[0]);
        assertTrue(((String) suite[2]).contains("--gpu-suite draws its own"), (String) suite[2]);
        Object[] twoRuns = CliTest.run("bench", "--gpu-suite", "--filtering", "-o", dir.toString());
        assertEquals(2, twoRuns[0]);
        assertTrue(((String) twoRuns[2]).contains("give one of them"), (String) twoRuns[2]);
        Object[] both = CliTest.run("bench", "--filtering", "--patch", dir.resolve("a.gsf").toString(),
                "--synthetic", "blazed-10um", "-o", dir.toString());
        assertEquals(2, both[0]);
        assertTrue(((String) both[2]).contains("not both"), (String) both[2]);
        Object[] sizes = CliTest.run("bench", "--filtering", "--synthetic", "blazed-10um", "--pixel-size", "0.1",
                "-o", dir.toString());
        assertEquals(2, sizes[0]);
        assertTrue(((String) sizes[2]).contains("a --synthetic patch has its own"), (String) sizes[2]);
    }
}
