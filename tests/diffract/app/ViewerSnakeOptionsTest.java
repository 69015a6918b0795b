package diffract.app;

import diffract.geometry.SnakeMesh;
import diffract.geometry.SnakeSpecies;
import diffract.scene.Scene;
import diffract.scene.SceneFile;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

/** The snake that {@code view --shape snake} and {@code render --shape snake} describe without a scene file. */
class ViewerSnakeOptionsTest {
    private static Scene scene(String... args) {
        RenderCommand command = new RenderCommand();
        String[] withOutput = java.util.Arrays.copyOf(args, args.length + 2);
        withOutput[args.length] = "-o";
        withOutput[args.length + 1] = "unused.png";
        new CommandLine(command).parseArgs(withOutput);
        command.options.validate();
        return command.options.scene(new Scene.ImageSize(800, 600));
    }

    private static double distance(Scene s) {
        double[] e = s.camera().eye();
        return Math.sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    }

    @Test
    void theSnakeWearsItsSpeciesScalesAndPigmentCoiledAndFramed() {
        Scene s = scene("--shape", "snake");
        assertEquals(SnakeSpecies.ELAPHE_GUTTATA, s.shape().scales().species());
        assertEquals(SnakeSpecies.ELAPHE_GUTTATA.scales(), s.shape().scales().lattice());
        assertEquals(SnakeSpecies.ELAPHE_GUTTATA, s.material().pigmentation().species());
        assertEquals(SnakeMesh.Pose.COILED, s.shape().pose());
        assertEquals(ViewerOptions.SNAKE_DISTANCE, distance(s), 1e-9);
        assertEquals(diffract.colour.MirrorNormalisation.ENERGY, s.material().settings().spectral().normalisation());
        assertEquals(diffract.optics.RadiometricGain.of(s.material().settings()), s.material().exposure(), 0,
                "the demo scene's radiometric gain");
        assertEquals(ViewerOptions.SNAKE_DIFFUSE_WEIGHT, s.material().diffuseWeight(), 0);

        Scene x = scene("--shape", "snake", "--species", "xenopeltisUnicolor", "--exposure", "100",
                "--distance", "3");
        assertEquals(SnakeSpecies.XENOPELTIS_UNICOLOR, x.shape().scales().species());
        assertEquals(SnakeSpecies.XENOPELTIS_UNICOLOR, x.material().pigmentation().species());
        assertEquals(100, x.material().exposure(), 0, "an exposure given wins over the snake's");
        assertEquals(diffract.colour.MirrorNormalisation.PEAK, x.material().settings().spectral().normalisation(),
                "a gain of one's own is against the thesis' normalisation, as in a scene file");
        assertEquals(3, distance(x), 1e-9, "a distance given wins over the snake's");
    }

    @Test
    void aSmoothSkinHasNoScalesAndOtherShapesKeepTheirDefaults() {
        Scene smooth = scene("--shape", "snake", "--smooth-skin");
        assertNull(smooth.shape().scales());
        assertEquals(true, smooth.material().pigmentation().procedural());
        Scene sphere = scene();
        assertNull(sphere.shape().scales());
        assertEquals(3.5, distance(sphere), 1e-9);
        assertEquals(400, sphere.material().exposure(), 0);
    }

    @Test
    void anUnknownSpeciesIsRefusedByName() {
        RenderCommand command = new RenderCommand();
        CommandLine.ParameterException e = assertThrows(CommandLine.ParameterException.class,
                () -> new CommandLine(command).parseArgs("--shape", "snake", "--species", "boa"));
        assertEquals(true, e.getMessage().contains("elapheGuttata or xenopeltisUnicolor"), e.getMessage());
    }

    /** The scene files the GPU suite times the viewer with describe the viewer's own default views. */
    @Test
    void theViewerScenesAreTheViewersDefaults() {
        assertSameView(SceneFile.load(Path.of("assets/scenes/viewer-sphere.json")), viewScene());
        assertSameView(SceneFile.load(Path.of("assets/scenes/viewer-snake.json")), viewScene("--shape", "snake"));
    }

    private static Scene viewScene(String... args) {
        ViewCommand command = new ViewCommand();
        new CommandLine(command).parseArgs(args);
        command.options.defaultVariant(diffract.optics.Variant.BAKED);
        command.options.validate();
        return command.options.scene(new Scene.ImageSize(800, 600));
    }

    private static void assertSameView(Scene file, Scene options) {
        assertArrayEquals(options.camera().eye(), file.camera().eye(), 1e-5);
        assertArrayEquals(options.camera().lookAt(), file.camera().lookAt(), 1e-12);
        assertEquals(options.camera().fieldOfViewDeg(), file.camera().fieldOfViewDeg(), 1e-12);
        assertArrayEquals(options.light().towardsLight(), file.light().towardsLight(), 1e-12);
        assertEquals(options.shape().kind(), file.shape().kind());
        assertEquals(options.shape().pose(), file.shape().pose());
        assertEquals(options.shape().scales(), file.shape().scales());
        assertEquals(options.material().settings(), file.material().settings());
        assertEquals(options.material().pigmentation(), file.material().pigmentation());
        assertEquals(options.material().exposure(), file.material().exposure(), 0);
        assertEquals(options.material().diffuseWeight(), file.material().diffuseWeight(), 0);
    }
}
