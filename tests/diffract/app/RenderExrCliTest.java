package diffract.app;

import diffract.colour.Srgb;
import diffract.colour.ToneMapping;
import diffract.jrtr.GlTestSupport;
import diffract.util.OpenExr;
import diffract.util.TestReport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code render -o OUT.exr}: the frame as linear light. What the PNG of the same frame shows is that light tone
 * mapped (the scene's operator, here on the CPU by {@link ToneMapping}), clipped and sRGB-encoded, so the two files
 * agree pixel by pixel to the PNG's rounding (and the shader's float32 against the CPU's double); the EXR keeps what
 * the PNG clips.
 */
@Tag("gl")
class RenderExrCliTest {
    @TempDir
    Path dir;

    static final int W = 48;
    static final int H = 32;

    /** Renders {@code scene} as PNG and EXR and compares; returns the EXR's brightest value. */
    private double assertExrIsThePngsLinearLight(String scene, ToneMapping operator, String... options)
            throws Exception {
        Path png = dir.resolve("frame.png");
        Path exr = dir.resolve("frame.exr");
        for (Path out : new Path[] {png, exr}) {
            String[] args = new String[5 + options.length];
            args[0] = "render";
            args[1] = scene;
            args[2] = "--size";
            args[3] = W + "x" + H;
            System.arraycopy(options, 0, args, 4, options.length);
            args[args.length - 1] = "-o";
            args = java.util.Arrays.copyOf(args, args.length + 1);
            args[args.length - 1] = out.toString();
            Object[] result = CliTest.run(args);
            assertEquals(0, result[0], (String) result[2]);
        }
        BufferedImage picture = ImageIO.read(png.toFile());
        OpenExr.Image image = OpenExr.read(exr);
        assertEquals(W, image.width());
        assertEquals(H, image.height());
        assertArrayEquals(OpenExr.REC709_D65_CHROMATICITIES, image.chromaticities());
        float[] r = image.channel("R");
        float[] g = image.channel("G");
        float[] b = image.channel("B");
        double brightest = 0;
        int worst = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int p = y * W + x;
                double[] display = operator.apply(new double[] {r[p], g[p], b[p]});
                int rgb = picture.getRGB(x, y);
                int[] shown = {(rgb >> 16) & 0xff, (rgb >> 8) & 0xff, rgb & 0xff};
                for (int c = 0; c < 3; c++) {
                    int expected = (int) Math.round(255 * Srgb.encode(Math.min(1, Math.max(0, display[c]))));
                    worst = Math.max(worst, Math.abs(expected - shown[c]));
                }
                brightest = Math.max(brightest, Math.max(r[p], Math.max(g[p], b[p])));
            }
        }
        TestReport.printf(RenderExrCliTest.class, Locale.ROOT, "%s %s: brightest linear value %.4g, largest "
                + "difference from the PNG %d of 255%n", Path.of(scene).getFileName(), String.join(" ", options),
                brightest, worst);
        assertTrue(worst <= 2, "the PNG is the EXR tone mapped and encoded: off by " + worst + " of 255");
        return brightest;
    }

    /** The thesis' surface (no staging): the PNG clips, the EXR holds light above white. */
    @Test
    void aPlainSurfaceKeepsWhatThePngClips() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        String scene = Path.of("assets", "scenes", "blazed-grating-plane.json").toString();
        double brightest = assertExrIsThePngsLinearLight(scene, ToneMapping.clip(), "--exposure", "40000");
        assertTrue(brightest > 1, "light above white is kept, not clipped: brightest " + brightest);
    }

    /** A staged surface and its ground, Reinhard tone mapped in the PNG, linear in the EXR. */
    @Test
    void aStagedSceneIsLinearBeforeItsToneMapping() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        Path scene = dir.resolve("staged.json");
        Files.writeString(scene, """
                {
                  "camera": {"eye": [0, 1.2, 3.2], "lookAt": [0, 0, 0], "fieldOfViewDeg": 45},
                  "light": {"thetaDeg": 30, "phiDeg": 0},
                  "ground": {"albedoSrgb": [0.4, 0.36, 0.27], "mottle": 0.3, "shadows": false},
                  "toneMapping": {"operator": "reinhard", "exposureStops": 1, "whiteLuminance": 3},
                  "shape": {"kind": "sphere"},
                  "material": {
                    "patch": {"procedural": "blazed", "periodUm": 2.5, "heightUm": 0.2, "periods": 4,
                              "samplesPerPeriod": 16, "rows": 8},
                    "variant": "flss",
                    "taylorTerms": 8,
                    "coherenceLengthUm": 10,
                    "exposure": 400
                  }
                }
                """);
        // the EXR holds the light after the exposure's stops, before the operator
        assertExrIsThePngsLinearLight(scene.toString(), new ToneMapping(ToneMapping.Operator.REINHARD, 0, 3));
    }
}
