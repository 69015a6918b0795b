package diffract.app;

import diffract.jrtr.GlTestSupport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code --dump-scene}: what a command line describes, with or without a scene file, written as a scene file that
 * draws the same picture, byte for byte.
 */
@Tag("gl")
class DumpSceneCliTest {
    @TempDir
    Path dir;

    @Test
    void optionsAloneDumpASceneThatRendersTheSamePicture() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        String[] options = {"--synthetic", "blazed", "--shape", "sphere", "--size", "40x32", "--theta-i", "35",
            "--azimuth", "20", "--variant", "flss", "--terms", "8"};
        assertSameAsDumped(options, "options");
    }

    @Test
    void aSceneWithOverridesDumpsTheOverriddenScene() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        String scene = Path.of("assets", "scenes", "blazed-grating-plane.json").toString();
        Object[] dumped = CliTest.run("render", scene, "--theta-i", "40", "--exposure", "7", "--dump-scene");
        assertEquals(0, dumped[0], (String) dumped[2]);
        String text = (String) dumped[1];
        assertTrue(text.contains("\"exposure\" : 7.0"), text);
        assertTrue(text.contains("\"direction\" : [ "), text);
        assertSameAsDumped(new String[] {scene, "--theta-i", "40", "--exposure", "7", "--elevation", "50",
            "--size", "40x32"}, "scene");
    }

    @Test
    void dumpingDrawsNothingAndNeedsNoOutput() {
        Object[] result = CliTest.run("render", "--synthetic", "blazed", "--dump-scene");
        assertEquals(0, result[0], (String) result[2]);
        assertTrue(((String) result[1]).startsWith("{"), (String) result[1]);
        assertFalse(((String) result[1]).contains("wrote"), (String) result[1]);
        result = CliTest.run("render", "--synthetic", "blazed", "--variant", "auto", "--dump-scene");
        assertEquals(2, result[0]);
        assertTrue(((String) result[2]).contains("--variant auto"), (String) result[2]);
    }

    /** Renders the options, dumps them, renders the dump: the same PNG bytes. */
    private void assertSameAsDumped(String[] options, String name) throws Exception {
        Path direct = dir.resolve(name + "-direct.png");
        Object[] result = CliTest.run(concat(new String[] {"render"}, options, new String[] {"-o", direct.toString()}));
        assertEquals(0, result[0], (String) result[2]);
        Object[] dumped = CliTest.run(concat(new String[] {"render"}, options, new String[] {"--dump-scene"}));
        assertEquals(0, dumped[0], (String) dumped[2]);
        Path scene = dir.resolve(name + ".json");
        Files.writeString(scene, (String) dumped[1]);
        Path fromScene = dir.resolve(name + "-scene.png");
        result = CliTest.run("render", scene.toString(), "-o", fromScene.toString());
        assertEquals(0, result[0], (String) result[2]);
        assertArrayEquals(Files.readAllBytes(direct), Files.readAllBytes(fromScene), name + ": the dumped scene's picture");
    }

    private static String[] concat(String[]... parts) {
        return java.util.Arrays.stream(parts).flatMap(java.util.Arrays::stream).toArray(String[]::new);
    }
}
