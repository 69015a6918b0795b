package diffract.app;

import diffract.jrtr.GlTestSupport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** {@code render --turntable}: as many frames as asked, of the asked size, and the frames differ as things turn. */
@Tag("gl")
class TurntableCliTest {
    @TempDir
    Path dir;

    static final String SCENE = Path.of("assets", "scenes", "blazed-grating-plane.json").toString();

    @Test
    void aGifHasEveryFrameAtTheAskedSize() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        Path gif = dir.resolve("turn.gif");
        Object[] result = CliTest.run("render", SCENE, "--turntable", "4", "--size", "48x32", "-o", gif.toString());
        assertEquals(0, result[0], (String) result[2]);
        assertTrue(((String) result[1]).contains("4 frames of 48x32"), (String) result[1]);
        try (ImageInputStream in = ImageIO.createImageInputStream(gif.toFile())) {
            ImageReader reader = ImageIO.getImageReaders(in).next();
            reader.setInput(in);
            assertEquals(4, reader.getNumImages(true));
            BufferedImage first = reader.read(0);
            BufferedImage second = reader.read(1);
            assertEquals(48, first.getWidth());
            assertEquals(32, first.getHeight());
            // a quarter turn of the camera shows the plane from the side: not the same picture
            assertNotEquals(java.util.Arrays.toString(first.getRGB(0, 0, 48, 32, null, 0, 48)),
                    java.util.Arrays.toString(second.getRGB(0, 0, 48, 32, null, 0, 48)));
            reader.dispose();
        }
    }

    @Test
    void aPngNameGivesANumberedSequenceAndTheLightCanGoRound() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        Path png = dir.resolve("light.png");
        Object[] result = CliTest.run("render", SCENE, "--turntable", "3", "--orbit-light", "--size", "40x24", "-o",
                png.toString());
        assertEquals(0, result[0], (String) result[2]);
        for (int k = 0; k < 3; k++) {
            Path frame = dir.resolve(String.format("light-%03d.png", k));
            assertTrue(Files.isRegularFile(frame), frame + " missing");
            BufferedImage image = ImageIO.read(frame.toFile());
            assertEquals(40, image.getWidth());
            assertEquals(24, image.getHeight());
        }
        assertTrue(!Files.exists(dir.resolve("light-003.png")));
    }

    @Test
    void aTurntableInPiecesMergesIntoTheSameGifAndSequenceBitForBit() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        String[] scene = {"render", SCENE, "--turntable", "5", "--size", "40x24", "--frame-ms", "120"};
        Path wholeGif = dir.resolve("whole.gif");
        Object[] result = CliTest.run(concat(scene, "-o", wholeGif.toString()));
        assertEquals(0, result[0], (String) result[2]);
        Path wholePng = dir.resolve("whole.png");
        result = CliTest.run(concat(scene, "-o", wholePng.toString()));
        assertEquals(0, result[0], (String) result[2]);
        Path pieces = dir.resolve("pieces");
        // pieces out of order, as workers finish: 2 of 3 first
        for (int i : new int[] {2, 0, 1}) {
            result = CliTest.run(concat(scene, "--tile", i + "/3", "--pieces", pieces.toString()));
            assertEquals(0, result[0], (String) result[2]);
            assertTrue(((String) result[1]).contains("wrote piece " + i + "/3 (frames "), (String) result[1]);
        }
        Path mergedGif = dir.resolve("merged.gif");
        result = CliTest.run("merge", pieces.toString(), "-o", mergedGif.toString());
        assertEquals(0, result[0], (String) result[2]);
        assertTrue(((String) result[1]).contains("merged 3 pieces into " + mergedGif + " (5 frames)"),
                (String) result[1]);
        assertArrayEquals(Files.readAllBytes(wholeGif), Files.readAllBytes(mergedGif), "the merged GIF");
        Path mergedPng = dir.resolve("merged.png");
        result = CliTest.run("merge", pieces.toString(), "-o", mergedPng.toString());
        assertEquals(0, result[0], (String) result[2]);
        for (int k = 0; k < 5; k++) {
            String frame = String.format("-%03d.png", k);
            assertArrayEquals(Files.readAllBytes(dir.resolve("whole" + frame)),
                    Files.readAllBytes(dir.resolve("merged" + frame)), "frame " + k);
        }
        assertTrue(!Files.exists(dir.resolve("merged-005.png")));
        // the pieces hold different frames: a merge of the first piece's frames alone would not do
        Files.delete(pieces.resolve("piece-1-of-3.json"));
        result = CliTest.run("merge", pieces.toString(), "-o", dir.resolve("again.gif").toString());
        assertEquals(2, result[0]);
        assertTrue(((String) result[2]).contains("piece 1/3 is missing: run render --tile 1/3"), (String) result[2]);
    }

    @Test
    void submitRendersATurntableInTwoWorkersAsOneRunWould() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        String[] scene = {"render", SCENE, "--turntable", "4", "--orbit-light", "--size", "32x24"};
        Path whole = dir.resolve("whole.gif");
        Object[] result = CliTest.run(concat(scene, "-o", whole.toString()));
        assertEquals(0, result[0], (String) result[2]);
        Path merged = dir.resolve("submitted.gif");
        String[] submit = {"submit", "--local", "2", "--piece-count", "3", "--cpus-per-task", "1", "--"};
        result = CliTest.run(concat(concat(submit, scene), "-o", merged.toString()));
        assertEquals(0, result[0], (String) result[2]);
        assertTrue(((String) result[1]).contains("3 pieces of 4 frames on 2 local workers of 1 processor each"), (String) result[1]);
        assertArrayEquals(Files.readAllBytes(whole), Files.readAllBytes(merged), "the GIF submit leaves");
    }

    @Test
    void turntablePiecesRefuseWhatOnlyMergeWrites() {
        Object[] result = CliTest.run("render", SCENE, "--turntable", "4", "--tile", "0/2", "--pieces",
                dir.resolve("p").toString(), "-o", dir.resolve("x.gif").toString());
        assertEquals(2, result[0]);
        assertTrue(((String) result[2]).contains("written by 'diffract merge"), (String) result[2]);
        result = CliTest.run("render", SCENE, "--tile", "0/2", "--pieces", dir.resolve("p").toString());
        assertEquals(2, result[0]);
        assertTrue(((String) result[2]).contains("add --turntable FRAMES"), (String) result[2]);
        result = CliTest.run("render", SCENE, "--turntable", "3", "--tile", "0/4", "--pieces",
                dir.resolve("p").toString());
        assertEquals(2, result[0]);
        assertTrue(((String) result[2]).contains("has only 3 frames to split"), (String) result[2]);
        result = CliTest.run("render", SCENE);
        assertEquals(2, result[0]);
        assertTrue(((String) result[2]).contains("render needs -o"), (String) result[2]);
    }

    private static String[] concat(String[] head, String... tail) {
        String[] all = java.util.Arrays.copyOf(head, head.length + tail.length);
        System.arraycopy(tail, 0, all, head.length, tail.length);
        return all;
    }

    @Test
    void badTurntableUsageIsOneLine() {
        Object[] result = CliTest.run("render", SCENE, "--turntable", "1", "-o", dir.resolve("x.gif").toString());
        assertEquals(2, result[0]);
        assertTrue(((String) result[2]).contains("2..720"), (String) result[2]);
        result = CliTest.run("render", SCENE, "--orbit-light", "-o", dir.resolve("x.png").toString());
        assertEquals(2, result[0]);
        assertTrue(((String) result[2]).contains("--turntable"), (String) result[2]);
    }
}
