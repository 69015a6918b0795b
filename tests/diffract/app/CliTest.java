package diffract.app;

import diffract.optics.BrdfMap;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.Levelling;
import diffract.optics.patches.PatchCatalogue;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.Variant;
import diffract.optics.io.GsfWriter;
import diffract.optics.io.HeightFieldReader;
import diffract.util.ImageFiles;
import diffract.util.Reporter;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The command line as a user meets it: exit codes, one-line errors, files written, reuse of precomputed terms. */
class CliTest {
    @TempDir
    static Path dir;
    static Path grating;

    @BeforeAll
    static void writeGrating() throws Exception {
        grating = dir.resolve("blazed.gsf");
        GsfWriter.write(grating, SyntheticPatches.blazed(2.5, 0.13, 10, 8, 4));
    }

    /** Runs the CLI in-process and returns {exit code, stdout, stderr}. */
    static Object[] run(String... args) {
        PrintStream out = System.out;
        PrintStream err = System.err;
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(o, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(e, true, StandardCharsets.UTF_8));
            int code = Main.execute(args);
            return new Object[] {code, o.toString(StandardCharsets.UTF_8), e.toString(StandardCharsets.UTF_8)};
        } finally {
            System.setOut(out);
            System.setErr(err);
        }
    }

    @Test
    void precomputeWritesTermsAndARerunReusesThem() {
        Path terms = dir.resolve("terms");
        Object[] first = run("precompute", "--patch", grating.toString(), "--terms", "12", "-o", terms.toString());
        assertEquals(0, first[0], (String) first[2]);
        assertTrue(((String) first[1]).startsWith("computed 13 terms"), (String) first[1]);
        assertTrue(Files.isRegularFile(terms.resolve("terms.f32")));
        assertTrue(Files.isRegularFile(terms.resolve("terms.json")));
        Object[] second = run("precompute", "--patch", grating.toString(), "--terms", "12", "-o", terms.toString());
        assertEquals(0, second[0]);
        assertTrue(((String) second[1]).startsWith("reused 13 terms"), (String) second[1]);
    }

    @Test
    void toleranceChoosesAndPrintsN() {
        Object[] result = run("precompute", "--patch", grating.toString(), "--tolerance", "1e-6", "-o",
                dir.resolve("tol").toString());
        assertEquals(0, result[0], (String) result[2]);
        assertTrue(((String) result[2]).contains("remainder bound"), (String) result[2]);
        assertTrue(((String) result[2]).matches("(?s).*Taylor order N = \\d+ .*"), (String) result[2]);
    }

    @Test
    void brdfMapWritesPngAndPfmOfTheRequestedSize() throws Exception {
        Path png = dir.resolve("map.png");
        Path pfm = dir.resolve("map.pfm");
        Object[] result = run("brdfmap", "--patch", grating.toString(), "--theta-i", "30", "--variant", "flss",
                "--terms", "10", "--size", "24", "-o", png.toString(), "--pfm", pfm.toString());
        assertEquals(0, result[0], (String) result[2]);
        BufferedImage image = ImageIO.read(png.toFile());
        assertEquals(24, image.getWidth());
        assertEquals(24, image.getHeight());
        assertEquals(0, image.getRGB(0, 0) & 0xffffff, "outside the unit disk is black");
        int[] whc = new int[3];
        float[] floats = ImageFiles.readPfm(pfm, whc);
        assertEquals(24, whc[0]);
        assertEquals(3, whc[2]);
        for (float f : floats) {
            assertTrue(Float.isFinite(f));
        }
    }

    @Test
    void monochromaticMapHoldsTheRelativeBrdfOfEachPixelDirectionInItsPfm() throws Exception {
        Path pfm = dir.resolve("mono.pfm");
        // a short coherence length (4 sigma_s = 2 um) widens the orders so that many pixels are lit
        Object[] result = run("brdfmap", "--patch", grating.toString(), "--theta-i", "20", "--lambda", "550",
                "--coherence-length", "2", "--variant", "reference", "--size", "16",
                "-o", dir.resolve("mono.png").toString(), "--pfm", pfm.toString());
        assertEquals(0, result[0], (String) result[2]);
        int[] whc = new int[3];
        float[] rho = ImageFiles.readPfm(pfm, whc);
        assertEquals(1, whc[2]);
        // the field as brdfmap reads it by default (the format's levelling)
        HeightField patch = HeightFieldReader.load(grating, null, null, null, null, Reporter.SILENT);
        BrdfSettings settings = BrdfSettings.builder(Variant.REFERENCE).highestOrder(30).windowRadius(1).lambdaRangeNm(380, 780).lambdaStepNm(5).coherenceLengthUm(4 * 0.5).pqReplicas(0).build();
        DiffractionBrdf brdf = DiffractionBrdf.create(settings, patch, null);
        Direction wi = Direction.fromSphericalDeg(20, 0);
        int lit = 0;
        for (int j = 0; j < 16; j++) {
            for (int i = 0; i < 16; i++) {
                double x = BrdfMap.xOf(i, 16);
                double y = BrdfMap.yOf(j, 16);
                double expected = x * x + y * y < 1 ? brdf.relative(wi, Direction.fromProjected(x, y), 550) : 0;
                assertEquals((float) expected, rho[j * 16 + i], 1e-6 * Math.max(1e-30, Math.abs(expected)),
                        "pixel " + i + "," + j);
                lit += expected > 1e-6 ? 1 : 0;
            }
        }
        assertTrue(lit > 5, "only " + lit + " pixels lit");
    }

    @Test
    void badInputEndsWithOneLineAndExitCode2() {
        Object[] missing = run("brdfmap", "--patch", dir.resolve("nope.png").toString(), "--theta-i", "10",
                "--max-height", "0.3", "--pixel-size", "0.1", "-o", dir.resolve("x.png").toString());
        assertEquals(2, missing[0]);
        String err = (String) missing[2];
        assertTrue(err.startsWith("diffract: "), err);
        assertEquals(1, err.strip().lines().count(), err);
        assertFalse(err.contains("Exception"), err);

        Object[] badVariant = run("brdfmap", "--patch", grating.toString(), "--theta-i", "10", "--variant", "fast",
                "-o", dir.resolve("x.png").toString());
        assertEquals(2, badVariant[0]);
        assertTrue(((String) badVariant[2]).contains("unknown variant 'fast'"), (String) badVariant[2]);

        Object[] badAngle = run("brdfmap", "--patch", grating.toString(), "--theta-i", "95", "-o",
                dir.resolve("x.png").toString());
        assertEquals(2, badAngle[0]);

        Object[] bothOrders = run("precompute", "--patch", grating.toString(), "--terms", "3", "--tolerance", "1e-3",
                "-o", dir.resolve("y").toString());
        assertEquals(2, bothOrders[0]);

        Object[] noCommand = run();
        assertEquals(2, noCommand[0]);

        // the baked table is GPU-only, bad radius and grid values are one line each
        for (String[] args : new String[][] {{"--variant", "baked"}, {"--window-radius", "wide"},
                {"--baked-samples", "12"}, {"--taylor-tolerance", "-1"}}) {
            String[] full = {"brdfmap", "--patch", grating.toString(), "--theta-i", "10", "--terms", "4",
                    "-o", dir.resolve("x.png").toString(), args[0], args[1]};
            Object[] bad = run(full);
            assertEquals(2, bad[0], String.join(" ", args) + ": " + bad[2]);
            assertEquals(1, ((String) bad[2]).strip().lines().count(), (String) bad[2]);
        }
    }

    @Test
    void compareReportsZeroForAMapAgainstItselfAndAnErrorForAGreyMap() {
        Path pfm = dir.resolve("self.pfm");
        assertEquals(0, run("brdfmap", "--patch", grating.toString(), "--theta-i", "10", "--variant", "flss",
                "--terms", "6", "--size", "12", "-o", dir.resolve("self.png").toString(), "--pfm", pfm.toString())[0]);
        Object[] same = run("compare", pfm.toString(), pfm.toString());
        assertEquals(0, same[0], (String) same[2]);
        assertTrue(((String) same[1]).contains("mean 0.000, p95 0.000, p99 0.000, max 0.00 over 112 pixels"), (String) same[1]);
        Path grey = dir.resolve("grey.pfm");
        assertEquals(0, run("brdfmap", "--patch", grating.toString(), "--theta-i", "10", "--lambda", "500",
                "--size", "12", "-o", dir.resolve("grey.png").toString(), "--pfm", grey.toString())[0]);
        Object[] wrong = run("compare", pfm.toString(), grey.toString());
        assertEquals(2, wrong[0]);
        assertTrue(((String) wrong[2]).contains("grey PFM"), (String) wrong[2]);
    }

    @Test
    void termsOfAnotherPatchAreRefused() throws Exception {
        Path other = dir.resolve("other.gsf");
        GsfWriter.write(other, SyntheticPatches.blazed(2.5, 0.13, 10, 4, 4));
        Path terms = dir.resolve("other-terms");
        assertEquals(0, run("precompute", "--patch", other.toString(), "--terms", "4", "-o", terms.toString())[0]);
        Object[] result = run("brdfmap", "--patch", grating.toString(), "--theta-i", "10", "--variant", "flss",
                "--terms", "4", "--terms-dir", terms.toString(), "--size", "8", "-o", dir.resolve("z.png").toString());
        assertEquals(2, result[0]);
        assertTrue(((String) result[2]).contains("was made from a 40x4 patch"), (String) result[2]);
    }

    /** Every named patch: the written .gsf holds the procedural field (float32 in metres) and its size. */
    @Test
    void patchWritesEveryNamedPatch() {
        for (PatchCatalogue.Entry entry : PatchCatalogue.ALL) {
            String kind = entry.name();
            Path gsf = dir.resolve(kind + ".gsf");
            boolean grating = entry.spec().kind().isGrating();
            Object[] result = grating ? run("patch", kind, "-o", gsf.toString())
                    : run("patch", kind, "--seed", "3", "-o", gsf.toString());
            assertEquals(0, result[0], (String) result[2]);
            HeightField read = HeightFieldReader.load(gsf, null, null, Reporter.SILENT);
            HeightField expected = (grating ? entry.spec() : entry.spec().withSeed(3)).build().meanSubtracted();
            assertEquals(expected.rows(), read.rows(), kind);
            assertEquals(expected.cols(), read.cols(), kind);
            assertEquals(expected.pixelSizeXUm(), read.pixelSizeXUm(), 1e-9, kind);
            double[] want = expected.heightsUm();
            double[] got = read.heightsUm();
            for (int i = 0; i < want.length; i++) {
                // float32 in metres: a relative rounding of 2^-24 on heights below 1 um
                if (Math.abs(want[i] - got[i]) > 1e-7) {
                    assertEquals(want[i], got[i], 1e-7, kind + " sample " + i);
                }
            }
        }
        Object[] unknown = run("patch", "zebra", "-o", dir.resolve("z.gsf").toString());
        assertEquals(2, unknown[0]);
        assertTrue(((String) unknown[2]).contains("use blazed, sinusoid, elaphe-like, xenopeltis-like, blazed-10um, elaphe-scan, elaphe-ridge, "
                + "xenopeltis-ridge, tall"),
                (String) unknown[2]);
    }

    @Test
    void everyCommandAnswersHelp() {
        for (String command : new String[] {"demo", "precompute", "brdfmap", "compare", "convert-terms", "patch"}) {
            Object[] result = run(command, "--help");
            assertEquals(0, result[0], command);
            assertTrue(((String) result[1]).contains("Usage: diffract " + command), (String) result[1]);
        }
    }
}
