package diffract.app;

import diffract.jrtr.GlTestSupport;
import diffract.util.TestReport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A scene whose surface pixels reach more lobes than the GL lets one fragment sum says so: the lobes method's
 * surface fragments write alpha 0 where their loops were ended early, and {@code render} counts them, over a still or
 * a turntable's frames, as {@code brdfmap} and the table's bake count theirs. A 32 x 32 sphere with a 37 um patch
 * (256 texels, 32 periods), every lobe within reach marched (no cutoff, no texel sums) at 4 nodes per sigma and 1 nm
 * at most: on llvmpipe, which ends a SIMD group's loops after 65535 iterations, hundreds of its pixels; with the
 * default quadrature none, on the sphere and in its BRDF map (whose black beyond the unit disk is drawn, not short).
 */
@Tag("gl")
class ShortPixelsCliTest {
    private static final String[] SPHERE = {"--shape", "sphere", "--synthetic", "elaphe-like", "--size-px", "256",
        "--periods", "32", "--variant", "lobes"};
    private static final String EVERY_LOBE = "cutoff=0,sumNodesPerBox=0,nodesPerSigma=4,maxStepNm=1";
    private static final Pattern WARNING = Pattern.compile("warning: (\\d+) of the (\\d+) pixels of the (frames?) "
            + "reach more lobes than (.+?) lets one fragment sum");

    @TempDir
    Path dir;

    private Object[] render(String size, String... more) {
        String[] args = new String[1 + SPHERE.length + 2 + more.length];
        args[0] = "render";
        System.arraycopy(SPHERE, 0, args, 1, SPHERE.length);
        args[1 + SPHERE.length] = "--size";
        args[2 + SPHERE.length] = size;
        System.arraycopy(more, 0, args, 3 + SPHERE.length, more.length);
        Object[] result = CliTest.run(args);
        assertEquals(0, result[0], (String) result[2]);
        return result;
    }

    private static boolean llvmpipe(Object[] result) {
        return ((String) result[2]).contains("llvmpipe");
    }

    @Test
    void aStillNamesItsPixelsLeftShort() {
        GlTestSupport.assumeOffscreenGl();
        Path png = dir.resolve("sphere.png");
        Object[] result = render("32x32", "--lobe-quadrature", EVERY_LOBE, "-o", png.toString());
        assertTrue(Files.isRegularFile(png), "the picture is written all the same");
        Matcher m = WARNING.matcher((String) result[2]);
        if (llvmpipe(result)) {
            assertTrue(m.find(), (String) result[2]);
            int shortPixels = Integer.parseInt(m.group(1));
            assertEquals(1024, Integer.parseInt(m.group(2)));
            assertEquals("frame", m.group(3));
            TestReport.line(ShortPixelsCliTest.class, "32 x 32 sphere, every lobe marched on " + m.group(4) + ": "
                    + shortPixels + " of 1024 pixels left short");
            assertTrue(shortPixels > 50 && shortPixels < 1024, "the sphere's pixels, not the background: "
                    + shortPixels);
            assertTrue(((String) result[2]).contains("draw it on a GPU, with --variant baked, or with a coarser "
                    + "--lobe-quadrature"), (String) result[2]);
        }

        Object[] plain = render("32x32", "-o", dir.resolve("default.png").toString());
        assertFalse(WARNING.matcher((String) plain[2]).find(), "the default quadrature: " + plain[2]);
        Object[] map = render("32x32", "--brdf-map", "-o", dir.resolve("map.png").toString());
        assertFalse(WARNING.matcher((String) map[2]).find(), "the BRDF map's black beyond the unit disk: " + map[2]);
    }

    @Test
    @Tag(diffract.jrtr.GlTestSupport.LONG_TAG) // a turntable of frames: a long test
    void aTurntableCountsThemOverItsFramesOnce() {
        GlTestSupport.assumeOffscreenGl();
        Object[] result = render("24x24", "--lobe-quadrature", EVERY_LOBE, "--turntable", "2", "-o",
                dir.resolve("turn.gif").toString());
        if (llvmpipe(result)) {
            Matcher m = WARNING.matcher((String) result[2]);
            assertTrue(m.find(), (String) result[2]);
            assertEquals(2 * 24 * 24, Integer.parseInt(m.group(2)));
            assertEquals("frames", m.group(3));
            assertFalse(m.find(), "one warning for the whole turntable: " + result[2]);
        }
    }
}
