package diffract.scene;

import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** A scene written by {@link SceneWriter} reads back as the same scene, and writes again as the same text. */
class SceneWriterTest {
    static List<Path> shippedScenes() throws IOException {
        try (Stream<Path> files = Files.list(Path.of("assets", "scenes"))) {
            return files.filter(f -> f.toString().endsWith(".json")).sorted().toList();
        }
    }

    @Test
    void everyShippedSceneReadsBackAsItselfAndWritesTheSameText() throws IOException {
        List<Path> scenes = shippedScenes();
        assertTrue(scenes.size() >= 5, "the shipped scenes: " + scenes);
        for (Path file : scenes) {
            Scene original = SceneFile.load(file);
            String text = SceneWriter.json(original);
            Scene again = SceneFile.parse(text, "dumped " + file, Path.of("/"), null);
            assertEquals(text, SceneWriter.json(again), file + ": written twice");
            assertEquals(original.material().settings(), again.material().settings(), file + ": the BRDF settings");
            assertEquals(original.material().patch(), again.material().patch(), file + ": the patch");
            assertEquals(original.material().exposure(), again.material().exposure(), file + ": the exposure");
            assertEquals(original.material().pigmentation(), again.material().pigmentation(), file + ": the pigment");
            assertEquals(original.image(), again.image(), file + ": the image");
            assertEquals(original.mode(), again.mode(), file + ": the mode");
            assertArrayEquals(original.camera().eye(), again.camera().eye(), file + ": the camera");
            assertArrayEquals(original.light().towardsLight(), again.light().towardsLight(), file + ": the light");
            assertEquals(original.shape().scales(), again.shape().scales(), file + ": the scales");
            assertEquals(original.stage().toneMapping(), again.stage().toneMapping(), file + ": the tone mapping");
            assertEquals(original.stage().environment(), again.stage().environment(), file + ": the environment");
        }
    }

    /** A method with its parameter is written with it and reads back as the same method. */
    @Test
    void aMethodWithItsParameterReadsBackAsItself() {
        Scene scene = SceneFile.parse("""
                {"camera": {"eye": [0, 0, 3]}, "light": {"thetaDeg": 30}, "shape": {"kind": "sphere"},
                 "material": {"patch": {"procedural": "blazed"}, "variant": {"type": "baked", "of": "flss"}}}
                """, "baked.json", Path.of("/"), null);
        String text = SceneWriter.json(scene);
        assertTrue(text.contains("\"variant\" : \"baked(of=flss)\""), text);
        Scene again = SceneFile.parse(text, "dumped", Path.of("/"), null);
        assertEquals(scene.material().settings().variant(), again.material().settings().variant());
        assertEquals(diffract.optics.Variant.BAKED.of(diffract.optics.Variant.FLSS),
                again.material().settings().variant());
    }

    @Test
    void theTextSpellsOutTheDefaultsAScenesFileLeavesOut() {
        Scene minimal = SceneFile.parse("""
                {"camera": {"eye": [0, 0, 3]}, "light": {"thetaDeg": 30},
                 "shape": {"kind": "sphere"}, "material": {"patch": {"procedural": "blazed"}}}
                """, "minimal.json", Path.of("/"), null);
        String text = SceneWriter.json(minimal);
        for (String key : List.of("\"coherenceLengthUm\" : 65.0", "\"variant\" : \"lobes\"", "\"window\" : \"averaged\"",
                "\"angularDiameterDeg\" : 0.53", "\"pixelFilter\" : \"box\"", "\"fieldOfViewDeg\" : 45.0")) {
            assertTrue(text.contains(key), key + " in\n" + text);
        }
        assertFalse(text.contains("environment"), "no stage was asked for:\n" + text);
    }

    /** The rigorous orders, an explicit resolution and a complex index are written and read back as themselves. */
    @Test
    void theRigorousSettingsReadBackAsThemselves() {
        Scene scene = SceneFile.parse("""
                {"camera": {"eye": [0, 0, 3]}, "light": {"thetaDeg": 30}, "shape": {"kind": "sphere"},
                 "material": {"patch": {"procedural": "elaphe-ridge"}, "orders": "rigorous", "harmonics": 25,
                  "layers": 9, "layerExtrapolation": false, "polarisation": "p", "extinction": 0.02}}
                """, "rigorous.json", Path.of("/"), null);
        String text = SceneWriter.json(scene);
        for (String key : List.of("\"orders\" : \"rigorous\"", "\"harmonics\" : 25", "\"layers\" : 9",
                "\"layerExtrapolation\" : false", "\"polarisation\" : \"p\"", "\"extinction\" : 0.02")) {
            assertTrue(text.contains(key), key + " in\n" + text);
        }
        Scene again = SceneFile.parse(text, "dumped", Path.of("/"), null);
        assertEquals(scene.material().settings(), again.material().settings());
    }

    @Test
    void theLocalWindowKeepsItsTiling() {
        Scene local = SceneFile.parse("""
                {"camera": {"eye": [0, 0, 3]}, "light": {"thetaDeg": 30}, "shape": {"kind": "sphere"},
                 "material": {"patch": {"procedural": "blazed"}, "variant": "flss", "window": "local",
                              "skinUmPerTexcoord": [120, 340]}}
                """, "local.json", Path.of("/"), null);
        String text = SceneWriter.json(local);
        assertTrue(text.contains("\"window\" : \"local\""), text);
        Scene again = SceneFile.parse(text, "again.json", Path.of("/"), null);
        assertEquals(local.material().settings(), again.material().settings());
    }

    @Test
    void overridesChangeTheSceneThatIsWritten() {
        Scene scene = SceneFile.parse("""
                {"camera": {"eye": [0, 0, 3]}, "light": {"thetaDeg": 30, "phiDeg": 90},
                 "shape": {"kind": "sphere"}, "material": {"patch": {"procedural": "blazed"}, "exposure": 12}}
                """, "o.json", Path.of("/"), null);
        Scene moved = new SceneOverrides(null, 40.0, null, 50.0, null, 3.0, null, false, true).applyTo(scene);
        double[] towards = moved.light().towardsLight();
        assertEquals(Math.cos(Math.toRadians(50)), towards[2] / Math.sqrt(towards[0] * towards[0]
                + towards[1] * towards[1] + towards[2] * towards[2]), 1e-12, "the light at 50 degrees");
        assertEquals(0, towards[0], 1e-12, "its azimuth kept (90 degrees)");
        double[] eye = moved.camera().eye();
        assertEquals(3 * Math.sin(Math.toRadians(40)), eye[1], 1e-12, "the camera raised to 40 degrees");
        assertEquals(3, Math.sqrt(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]), 1e-12, "at its distance");
        assertEquals(3.0, moved.material().exposure());
        assertEquals(DisplayMode.BRDF_MAP, moved.mode());
        assertNotEquals(SceneWriter.json(scene), SceneWriter.json(moved));
        Scene same = new SceneOverrides(null, null, null, null, null, null, null, false, false).applyTo(scene);
        assertEquals(SceneWriter.json(scene), SceneWriter.json(same), "no override, no change");
    }
}
