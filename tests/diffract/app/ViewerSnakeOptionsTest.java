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

    private static Scene shipped(String name) {
        return SceneFile.load(Path.of("assets/scenes", name));
    }

    /** --shape snake is the shipped viewer scene, drawn by the command's own method. */
    @Test
    void theSnakeIsTheShippedSceneDrawnByTheCommandsMethod() {
        Scene file = shipped("viewer-snake.json");
        Scene s = scene("--shape", "snake");
        assertSameView(file, s, diffract.optics.Variant.LOBES);
        assertEquals(SnakeSpecies.ELAPHE_GUTTATA, s.shape().scales().species());
        assertEquals(SnakeSpecies.ELAPHE_GUTTATA.scales(), s.shape().scales().lattice());
        assertEquals(SnakeSpecies.ELAPHE_GUTTATA, s.material().pigmentation().species());
        assertEquals(SnakeMesh.Pose.COILED, s.shape().pose());
        assertEquals(2.4, distance(s), 1e-5, "the coiled body fills an 800 x 600 window");
        assertEquals(diffract.colour.MirrorNormalisation.ENERGY, s.material().settings().spectral().normalisation());
        assertEquals(diffract.optics.RadiometricGain.of(s.material().settings()), s.material().exposure(), 0,
                "the demo scene's radiometric gain");
        assertEquals(0, s.material().diffuseWeight(), 0);
        assertEquals(diffract.optics.Variant.BAKED, viewScene("--shape", "snake").material().settings().variant(),
                "the viewer draws its baked table");
    }

    /** Options beside the snake override what they name, as beside any scene file. */
    @Test
    void optionsBesideTheSnakeOverrideWhatTheyName() {
        Scene x = scene("--shape", "snake", "--species", "xenopeltisUnicolor", "--exposure", "100",
                "--distance", "3");
        assertEquals(SnakeSpecies.XENOPELTIS_UNICOLOR, x.shape().scales().species());
        assertEquals(SnakeSpecies.XENOPELTIS_UNICOLOR.scales(), x.shape().scales().lattice());
        assertEquals(SnakeSpecies.XENOPELTIS_UNICOLOR, x.material().pigmentation().species());
        assertEquals(100, x.material().exposure(), 0, "an exposure given wins over the snake's");
        assertEquals(diffract.colour.MirrorNormalisation.ENERGY, x.material().settings().spectral().normalisation(),
                "the exposure is the gain alone: the scene's normalisation stays");
        assertEquals(3, distance(x), 1e-9, "a distance given wins over the snake's");

        Scene demo = scene(Path.of("assets/scenes/snake-elaphe.json").toString(), "--species", "xenopeltisUnicolor",
                "--tangent", "0,1,0");
        assertEquals(SnakeSpecies.XENOPELTIS_UNICOLOR, demo.shape().scales().species(), "beside a scene file too");
        assertEquals(SnakeSpecies.XENOPELTIS_UNICOLOR, demo.material().pigmentation().species());
        assertEquals(diffract.geometry.TangentSource.projected(0, 1, 0), demo.shape().tangents());
        Scene demoFile = shipped("snake-elaphe.json");
        assertArrayEquals(demoFile.camera().eye(), demo.camera().eye(), 0, "what is not named stays the scene's");
        assertEquals(demoFile.stage().environment(), demo.stage().environment());
        assertArrayEquals(demoFile.stage().ground().albedoSrgb(), demo.stage().ground().albedoSrgb(), 0);
    }

    @Test
    void aSmoothSkinHasNoScalesAndOtherShapesKeepTheirDefaults() {
        Scene smooth = scene("--shape", "snake", "--smooth-skin");
        assertNull(smooth.shape().scales());
        assertEquals(true, smooth.material().pigmentation().procedural());
        Scene image = scene("--shape", "snake", "--pigmentation", "pigment.png", "--no-pigmentation");
        assertEquals(Path.of("pigment.png"), image.material().pigmentation().file());
        assertEquals(false, image.material().pigmentationOn(), "--no-pigmentation starts it off");
        Scene sphere = scene();
        assertNull(sphere.shape().scales());
        assertEquals(3.5, distance(sphere), 1e-9);
        assertEquals(400, sphere.material().exposure(), 0);
        assertEquals(false, sphere.material().pigmentationOn());
    }

    @Test
    void aSpeciesOrASmoothSkinNeedsASnake() {
        RenderCommand command = new RenderCommand();
        new CommandLine(command).parseArgs("--species", "xenopeltisUnicolor", "-o", "unused.png");
        diffract.util.UserInputException e = assertThrows(diffract.util.UserInputException.class,
                command.options::validate);
        assertEquals(true, e.getMessage().contains("--species dresses a snake, and the shape is a sphere: add "
                + "--shape snake"), e.getMessage());
        RenderCommand plane = new RenderCommand();
        new CommandLine(plane).parseArgs("assets/scenes/blazed-grating-plane.json", "--smooth-skin", "-o", "u.png");
        e = assertThrows(diffract.util.UserInputException.class, plane.options::validate);
        assertEquals(true, e.getMessage().contains("--smooth-skin dresses a snake"), e.getMessage());
    }

    @Test
    void anUnknownSpeciesIsRefusedByName() {
        RenderCommand command = new RenderCommand();
        CommandLine.ParameterException e = assertThrows(CommandLine.ParameterException.class,
                () -> new CommandLine(command).parseArgs("--shape", "snake", "--species", "boa"));
        assertEquals(true, e.getMessage().contains("elapheGuttata or xenopeltisUnicolor"), e.getMessage());
    }

    /** The scene file the GPU suite times the viewer's sphere with describes the viewer's own default view. */
    @Test
    void theViewerSphereSceneIsTheViewersDefault() {
        assertSameView(shipped("viewer-sphere.json"), viewScene(), diffract.optics.Variant.BAKED);
    }

    private static Scene viewScene(String... args) {
        ViewCommand command = new ViewCommand();
        new CommandLine(command).parseArgs(args);
        ViewCommand.defaults(command.options);
        command.options.validate();
        return command.options.scene(new Scene.ImageSize(800, 600));
    }

    private static void assertSameView(Scene file, Scene options, diffract.optics.Variant variant) {
        assertArrayEquals(options.camera().eye(), file.camera().eye(), 1e-5);
        assertArrayEquals(options.camera().lookAt(), file.camera().lookAt(), 1e-12);
        assertEquals(options.camera().fieldOfViewDeg(), file.camera().fieldOfViewDeg(), 1e-12);
        assertArrayEquals(options.light().towardsLight(), file.light().towardsLight(), 1e-12);
        assertEquals(options.shape().kind(), file.shape().kind());
        assertEquals(options.shape().pose(), file.shape().pose());
        assertEquals(options.shape().scales(), file.shape().scales());
        assertEquals(options.material().settings(), file.material().settings().with(b -> b.variant(variant)));
        assertEquals(variant, options.material().settings().variant());
        assertEquals(options.material().pigmentation(), file.material().pigmentation());
        assertEquals(options.material().exposure(), file.material().exposure(), 0);
        assertEquals(options.material().diffuseWeight(), file.material().diffuseWeight(), 0);
    }
}
