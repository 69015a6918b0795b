package diffract.app;

import diffract.scene.Fabricator;
import diffract.scene.SceneFile;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The one-line warning where the scalar model is visibly off Maxwell's equations (docs/measurements/validity.md), on both sides of
 * the boundary, from brdfmap and from a scene: the Elaphe-like ridge at 30 degrees is warned of with the expected error
 * and the rigorous commands; a shallow 2.5 um sinusoid near the normal is not; the lobes with the rigorous orders are
 * not warned of.
 */
class ScalarValidityCliTest {
    @TempDir
    Path dir;

    @Test
    void brdfmapWarnsOnTheRidgeAndNotOnAShallowGrating() {
        Object[] ridge = CliTest.run("brdfmap", "--synthetic", "elaphe-ridge", "--theta-i", "30", "--variant", "lobes",
                "--size", "16", "-o", dir.resolve("ridge.png").toString());
        assertEquals(0, ridge[0], (String) ridge[2]);
        String warning = warning((String) ridge[2]);
        assertTrue(warning.contains("the scalar model is expected about CIEDE2000"), warning);
        assertTrue(warning.contains("period 1.14 um, 0.30 um deep, light at 30 degrees"), warning);
        assertTrue(warning.contains("diffract brdfmap --variant rigorous --synthetic elaphe-ridge --theta-i 30"), warning);
        assertTrue(warning.contains("--orders rigorous"), warning);

        Object[] shallow = CliTest.run("brdfmap", "--synthetic", "sinusoid", "--period", "2.5", "--height", "0.025",
                "--theta-i", "10", "--variant", "lobes", "--size", "16", "-o", dir.resolve("shallow.png").toString());
        assertEquals(0, shallow[0], (String) shallow[2]);
        assertFalse(((String) shallow[2]).contains("Maxwell"), (String) shallow[2]);
    }

    @Test
    void aSceneWarnsOnTheRidgeUnlessItsLobesTakeTheRigorousOrders() throws Exception {
        String scene = """
                {"camera": {"eye": [0, 0, 3]}, "light": {"thetaDeg": 30, "phiDeg": 90}, "shape": {"kind": "plane"},
                 "material": {"patch": {"procedural": "elaphe-ridge"}, "variant": "lobes", "taylorTerms": 8%s}}
                """;
        Reporter.Collecting scalar = new Reporter.Collecting();
        Fabricator.fabricate(SceneFile.parse(scene.formatted(""), "ridge.json", dir, null), scalar);
        assertEquals(1, scalar.warnings().stream().filter(w -> w.contains("Maxwell's equations")).count(),
                String.join("\n", scalar.warnings()));
        assertTrue(scalar.warnings().stream().anyMatch(w -> w.contains("\"orders\": \"rigorous\"")),
                String.join("\n", scalar.warnings()));
        // a cheap table: one 20 nm step, few harmonics and slabs
        Reporter.Collecting rigorous = new Reporter.Collecting();
        Fabricator.fabricate(SceneFile.parse(scene.formatted(", \"orders\": \"rigorous\", \"lambdaMinNm\": 500,"
                + " \"lambdaMaxNm\": 520, \"harmonics\": 8, \"layers\": 4"), "ridge.json", dir, null), rigorous);
        assertFalse(rigorous.warnings().stream().anyMatch(w -> w.contains("Maxwell's equations")),
                String.join("\n", rigorous.warnings()));
    }

    private static String warning(String err) {
        return err.lines().filter(l -> l.contains("Maxwell's equations")).findFirst().orElse("(none in: " + err + ")");
    }
}
