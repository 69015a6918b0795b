package diffract.app;

import diffract.jrtr.GlTestSupport;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.io.GsfWriter;
import diffract.util.ImageFiles;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** {@code brdfmap --engine gpu}: same files as the CPU engine, timing, texture formats, one-line refusals. */
class GpuCliTest {
    @TempDir
    static Path dir;
    static Path grating;

    @BeforeAll
    static void writeGrating() throws Exception {
        grating = dir.resolve("blazed.gsf");
        GsfWriter.write(grating, SyntheticPatches.blazed(2.5, 0.13, 10, 8, 4));
    }

    @Test
    @Tag("gl")
    void tallPatchesSwitchToThePhaseCentredExpansionOrWarnAndLowOnesDoNot() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        Path tall = dir.resolve("tall.gsf");
        GsfWriter.write(tall, SyntheticPatches.sinusoid(2.5, 1.2, 10, 4, 2)); // x = k |w| max|h| = 18.9 at 380 nm
        // --level none: the sinusoid as written (a plane fit tilts 4 periods of it and changes max|h|)
        String[] tallMap = {"brdfmap", "--patch", tall.toString(), "--level", "none", "--theta-i", "30", "--variant",
            "flss", "--terms", "60", "--engine", "gpu", "--size", "8", "-o", dir.resolve("tall.png").toString()};
        Object[] switched = CliTest.run(tallMap);
        assertEquals(0, switched[0], (String) switched[2]);
        assertTrue(((String) switched[2]).contains("phase-centred Taylor expansion: x = k|w|max|h| = 18.9"),
                (String) switched[2]);
        // the mesh renderer (viewer, render) switches the same way
        Object[] rendered = CliTest.run("render", "--patch", tall.toString(), "--level", "none", "--terms", "60",
                "--lambda-step", "20",
                "--size", "48x32", "-o", dir.resolve("tall-render.png").toString());
        assertEquals(0, rendered[0], (String) rendered[2]);
        assertTrue(((String) rendered[2]).contains("phase-centred Taylor expansion"), (String) rendered[2]);
        Object[] warned = CliTest.run(concat(tallMap, "--expansion", "plain"));
        assertEquals(0, warned[0], (String) warned[2]);
        assertTrue(((String) warned[2]).contains("warning: the float32 Taylor sum (61 terms) may err"), (String) warned[2]);
        Object[] quiet = CliTest.run("brdfmap", "--patch", grating.toString(), "--theta-i", "30", "--variant", "flss",
                "--terms", "20", "--engine", "gpu", "--size", "8", "-o", dir.resolve("low.png").toString());
        assertEquals(0, quiet[0], (String) quiet[2]);
        assertTrue(!((String) quiet[2]).contains("float32 Taylor sum"), (String) quiet[2]);
        assertTrue(!((String) quiet[2]).contains("phase-centred"), (String) quiet[2]);
    }

    @Test
    @Tag("gl")
    void gpuEngineWritesTheMapsAndTimesThem() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        Path cpuPfm = dir.resolve("cpu.pfm");
        Path gpuPfm = dir.resolve("gpu.pfm");
        String[] common = {"brdfmap", "--patch", grating.toString(), "--theta-i", "30", "--variant", "pq",
            "--terms", "10", "--size", "24", "--coherence-length", "10"};
        Object[] cpu = CliTest.run(concat(common, "-o", dir.resolve("cpu.png").toString(), "--pfm", cpuPfm.toString()));
        assertEquals(0, cpu[0], (String) cpu[2]);
        Object[] gpu = CliTest.run(concat(common, "--engine", "gpu", "--time", "-o", dir.resolve("gpu.png").toString(),
                "--pfm", gpuPfm.toString()));
        assertEquals(0, gpu[0], (String) gpu[2]);
        assertTrue(((String) gpu[1]).matches("(?s).*gpu \\d+\\.\\d ms/frame \\(pq, 24x24.*"), (String) gpu[1]);
        int[] whc = new int[3];
        float[] a = ImageFiles.readPfm(cpuPfm, whc);
        float[] b = ImageFiles.readPfm(gpuPfm, whc);
        float peak = 0;
        for (float v : a) {
            peak = Math.max(peak, Math.abs(v));
        }
        for (int i = 0; i < a.length; i++) {
            assertEquals(a[i], b[i], 1e-4 * peak, "linear sRGB value " + i);
        }
        Object[] half = CliTest.run(concat(common, "--engine", "gpu", "--texture-format", "rg16f", "--lambda", "550",
                "-o", dir.resolve("half.png").toString()));
        assertEquals(0, half[0], (String) half[2]);
        assertTrue(Files.size(dir.resolve("half.png")) > 0);
    }

    @Test
    void badGpuUsageEndsWithOneLine() {
        String out = dir.resolve("x.png").toString();
        Object[] reference = CliTest.run("brdfmap", "--patch", grating.toString(), "--theta-i", "10", "--engine", "gpu",
                "-o", out);
        assertEquals(2, reference[0]);
        assertEquals(1, ((String) reference[2]).strip().lines().count(), (String) reference[2]);
        assertTrue(((String) reference[2]).contains("CPU only"), (String) reference[2]);
        Object[] engine = CliTest.run("brdfmap", "--patch", grating.toString(), "--theta-i", "10", "--engine", "tpu",
                "-o", out);
        assertEquals(2, engine[0]);
        Object[] format = CliTest.run("brdfmap", "--patch", grating.toString(), "--theta-i", "10", "--variant", "flss",
                "--engine", "gpu", "--texture-format", "rgba8", "-o", out);
        assertEquals(2, format[0]);
        assertTrue(((String) format[2]).contains("--texture-format") && ((String) format[2]).contains("RG32F, RG16F, RG8"),
                (String) format[2]);
        Object[] time = CliTest.run("brdfmap", "--patch", grating.toString(), "--theta-i", "10", "--variant", "flss",
                "--time", "-o", out);
        assertEquals(2, time[0]);
    }

    /** compare: a map against itself is 0 everywhere; against a dimmer copy it is not. */
    @Test
    void compareReportsCiede2000OverTheDiskAndTheLitPixels() throws Exception {
        int size = 8;
        float[] map = new float[size * size * 3];
        float[] dimmer = new float[map.length];
        for (int i = 0; i < map.length; i++) {
            map[i] = 0.5f;
            dimmer[i] = 0.25f;
        }
        Path a = dir.resolve("a.pfm");
        Path b = dir.resolve("b.pfm");
        ImageFiles.writePfm(a, map, size, size, 3);
        ImageFiles.writePfm(b, dimmer, size, size, 3);
        Object[] same = CliTest.run("compare", a.toString(), a.toString());
        assertEquals(0, same[0], (String) same[2]);
        assertTrue(((String) same[1]).startsWith("CIEDE2000 mean 0.000, p95 0.000, p99 0.000, max 0.00 over 52 pixels; "
                + "lit: mean 0.000"), (String) same[1]);
        Object[] different = CliTest.run("compare", a.toString(), b.toString(), "--exposure", "2");
        assertEquals(0, different[0], (String) different[2]);
        assertTrue(((String) different[1]).matches("CIEDE2000 mean [1-9]\\d*\\.\\d+, .*lit: .* over 52 pixels.*\\s*"),
                (String) different[1]);
        Object[] missing = CliTest.run("compare", a.toString(), dir.resolve("nope.pfm").toString());
        assertEquals(2, missing[0]);
    }

    private static String[] concat(String[] a, String... b) {
        String[] r = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, r, a.length, b.length);
        return r;
    }
}
