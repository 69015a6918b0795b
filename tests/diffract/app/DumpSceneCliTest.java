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

    /**
     * The lobes method's knobs given on the command line are part of the dumped scene (material.lobeQuadrature): its
     * picture is the command's, and not the default quadrature's.
     */
    @Test
    void theLobesQuadratureIsDumped() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        String[] options = {"--synthetic", "blazed", "--shape", "sphere", "--size", "40x32", "--theta-i", "35",
            "--variant", "lobes", "--lobe-quadrature", "nodesPerSigma=0.2,maxStepNm=16,cutoff=1e-3"};
        Object[] dumped = CliTest.run(concat(new String[] {"render"}, options, new String[] {"--dump-scene"}));
        assertTrue(((String) dumped[1]).contains("\"nodesPerSigma\" : 0.2"), (String) dumped[1]);
        assertSameAsDumped(options, "quadrature");
        Path plain = dir.resolve("default-quadrature.png");
        Object[] result = CliTest.run(concat(new String[] {"render"}, java.util.Arrays.copyOf(options,
                options.length - 2), new String[] {"-o", plain.toString()}));
        assertEquals(0, result[0], (String) result[2]);
        assertFalse(java.util.Arrays.equals(Files.readAllBytes(plain),
                Files.readAllBytes(dir.resolve("quadrature-direct.png"))), "the knobs change the picture");
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
