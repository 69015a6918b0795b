package diffract.app;

import diffract.jrtr.GlTestSupport;
import diffract.render.GoldenImages;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code render SCENE --size 160x100} of every default scene, through the CLI as a user runs it (scene file,
 * Fabricator, cached terms, offscreen viewer renderer), against {@code tests/goldens/scenes/SCENE.png}.
 *
 * <p>Tolerance: 2/255 per channel and 1 % of the pixels (160 of 16,000). On one machine llvmpipe renders these
 * bit-identically run after run; another Mesa/LLVM may round a few ulps differently, which moves an 8-bit value by
 * at most a step where it sits on a rounding boundary (hence 2 steps), and may cover a silhouette pixel of the mesh
 * or a half-texel tie of the lookup differently: those are the pixels the budget absorbs. It is twice
 * {@code GoldenImageTest}'s 0.5 % because these pictures have mesh edges (the snake's outline is ~600 pixels long
 * at this size) where a BRDF map has none. A real regression (a wrong camera, light or tangent frame, a missing
 * term) moves whole bands of colour: thousands of pixels. Regenerate with
 * {@code xvfb-run -a mvn test -Dtest=SceneRenderGoldenTest -Ddiffract.updateGoldens=true}.
 */
@Tag("gl")
class SceneRenderGoldenTest {
    static final Path GOLDENS = Path.of("tests", "goldens", "scenes");
    static final int CHANNEL_TOLERANCE = 2;
    static final double PIXEL_BUDGET_PERCENT = 1.0;

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"snake-elaphe", "snake-xenopeltis", "blazed-grating-plane", "brdfmap-elaphe"})
    void renderOfEachDefaultSceneMatchesItsGolden(String name) throws Exception {
        GlTestSupport.assumeOffscreenGl();
        Files.createDirectories(GoldenImages.DIFFS);
        Path png = GoldenImages.DIFFS.resolve("scene-" + name + "-actual.png");
        Object[] result = CliTest.run("render", Path.of("assets", "scenes", name + ".json").toString(),
                "--size", "160x100", "-o", png.toString());
        assertEquals(0, result[0], (String) result[2]);
        assertTrue(((String) result[1]).contains("wrote " + png + " (160x100"), (String) result[1]);
        GoldenImages.assertMatches("scene-" + name, png, GOLDENS.resolve(name + ".png"), CHANNEL_TOLERANCE,
                PIXEL_BUDGET_PERCENT);
    }
}
