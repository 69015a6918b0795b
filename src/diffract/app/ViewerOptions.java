package diffract.app;

import diffract.bench.AutoChoice;
import diffract.bench.AutoVariant;
import diffract.geometry.SnakeMesh;
import diffract.geometry.TangentSource;
import diffract.optics.BrdfSettings;
import diffract.optics.Variant;
import diffract.render.DiffractionShaders;
import diffract.scene.DisplayMode;
import diffract.scene.Fabricator;
import diffract.scene.LightDirection;
import diffract.scene.OrbitCamera;
import diffract.scene.Scene;
import diffract.scene.SceneFile;
import diffract.scene.SceneSetup;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.TypeConversionException;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * What {@code view} and {@code render} show, as options. Without a SCENE file the options describe a scene (the
 * same {@link Scene} a file describes), which the {@link Fabricator} builds as it builds a file's; with one, the
 * options given override what they name (BRDF settings, light, camera angles, exposure, mode, pigmentation switch,
 * diffuse weight), and the options that name what only the scene may say (the patch, the shape) are refused.
 */
final class ViewerOptions {
    @Parameters(index = "0", arity = "0..1", paramLabel = "SCENE",
            description = "A scene file (JSON, docs/scene-format.md), e.g. assets/scenes/snake-elaphe.json; options "
                    + "given as well override what they name.")
    Path scene;

    @Spec(Spec.Target.MIXEE)
    CommandSpec mixee;

    @Mixin
    PatchOptions patch;

    @Mixin
    BrdfOptions brdf;

    @Option(names = "--shape", defaultValue = "sphere", paramLabel = "S", converter = ShapeConverter.class,
            completionCandidates = OptionTypes.ShapeNames.class,
            description = "${COMPLETION-CANDIDATES} (procedural, with corn-snake pigmentation; default ${DEFAULT-VALUE}).")
    Scene.ShapeKind shape;

    @Option(names = "--tangent", defaultValue = "1,0,0", paramLabel = "X,Y,Z", converter = OptionTypes.Vector3.Converter.class,
            description = "World direction of the patch's x axis (columns) on the shape, projected onto each surface point (default ${DEFAULT-VALUE}).")
    OptionTypes.Vector3 tangent;

    @Option(names = "--pigmentation", paramLabel = "IMAGE",
            description = "Pigment colours over the shape's texcoords (sRGB image); P toggles it.")
    Path pigmentation;

    @Option(names = "--no-pigmentation", description = "Start with the pigmentation off (structural colour only; P toggles it).")
    boolean noPigmentation;

    @Option(names = "--diffuse-weight", defaultValue = "0.2", paramLabel = "W",
            description = "w_d: pigment mixed in as ambient light (default ${DEFAULT-VALUE}).")
    double diffuseWeight;

    @Option(names = "--theta-i", defaultValue = "30", paramLabel = "DEG", description = "Light polar angle from the world z axis (default ${DEFAULT-VALUE}).")
    double thetaIDeg;

    @Option(names = "--phi-i", paramLabel = "DEG",
            description = "Light azimuth from the world x axis (default: in the plane of a named patch's period, 90 "
                    + "for the snake patches; else 0).")
    Double phiIDeg;

    @Option(names = "--exposure", defaultValue = "10", paramLabel = "E", description = "Multiplies linear XYZ before display (default ${DEFAULT-VALUE}).")
    double exposure;

    @Option(names = "--brdf-map", description = "Start with the BRDF map of the current light instead of the shape.")
    boolean brdfMap;

    @Option(names = "--azimuth", defaultValue = "0", paramLabel = "DEG", description = "Camera azimuth about the y axis (default ${DEFAULT-VALUE}).")
    double azimuthDeg;

    @Option(names = "--elevation", defaultValue = "20", paramLabel = "DEG", description = "Camera elevation (default ${DEFAULT-VALUE}).")
    double elevationDeg;

    @Option(names = "--distance", defaultValue = "3.5", paramLabel = "D", description = "Camera distance from the origin (default ${DEFAULT-VALUE}).")
    double distance;

    /** The patch a command line without --patch or --synthetic shows. */
    static final String DEFAULT_PATCH = "elaphe-like";

    /** What a scene file describes by itself: these options cannot be combined with one. */
    static final List<String> SCENE_ONLY = sceneOnly();

    /** The scene read by validate(). */
    private Scene parsedScene;

    private static List<String> sceneOnly() {
        List<String> names = new ArrayList<>(List.of(PatchOptions.NAMES));
        names.addAll(List.of("--shape", "--tangent", "--pigmentation"));
        return List.copyOf(names);
    }

    /** Accepts the shapes a command line can build (an OBJ file needs a scene). */
    static final class ShapeConverter implements ITypeConverter<Scene.ShapeKind> {
        @Override
        public Scene.ShapeKind convert(String text) {
            for (Scene.ShapeKind kind : Scene.ShapeKind.values()) {
                if (kind != Scene.ShapeKind.OBJ && kind.sceneName().equalsIgnoreCase(text.trim())) {
                    return kind;
                }
            }
            throw new TypeConversionException("unknown shape '" + text + "': use sphere, plane, cylinder or snake "
                    + "(an OBJ file needs a scene file)");
        }
    }

    /** Everything checked that needs no OpenGL: bad usage fails before any work, a bad scene file too. */
    void validate() {
        if (scene != null) {
            for (String option : SCENE_ONLY) {
                if (given(option)) {
                    throw new UserInputException(option + " cannot be combined with a SCENE: the scene file says "
                            + "that (edit " + scene + ", or leave the SCENE out)");
                }
            }
            parsedScene = SceneFile.load(scene);
        }
        patch.validate();
        brdf.validate();
        if (brdf.variantOr(Variant.FLSS) == Variant.REFERENCE) {
            throw new UserInputException(DiffractionShaders.REFERENCE_IS_CPU_ONLY
                    + " (the reference is drawn by ./diffract brdfmap)");
        }
        brdf.apply(BrdfSettings.thesis(Variant.FLSS)); // a refused value fails now too
        if (!(distance >= OrbitCamera.MIN_DISTANCE && distance <= OrbitCamera.MAX_DISTANCE)) {
            throw new UserInputException("--distance must be in [" + OrbitCamera.MIN_DISTANCE + ", "
                    + OrbitCamera.MAX_DISTANCE + "], got " + distance);
        }
        if (!(thetaIDeg >= 0 && thetaIDeg <= LightDirection.MAX_THETA_DEG)) {
            throw new UserInputException("--theta-i must be in [0, " + LightDirection.MAX_THETA_DEG + "] degrees, got "
                    + thetaIDeg);
        }
        if (!Double.isFinite(azimuthDeg) || !Double.isFinite(elevationDeg) || (phiIDeg != null && !Double.isFinite(phiIDeg))) {
            throw new UserInputException("angles must be finite numbers");
        }
    }

    /** Whether the user gave {@code option} on the command line (not just its default). */
    boolean given(String option) {
        return mixee != null && mixee.commandLine() != null && mixee.commandLine().getParseResult() != null
                && mixee.commandLine().getParseResult().hasMatchedOption(option);
    }

    /** The scene file's image size, or {@code fallback} without a scene file (validate() first). */
    Scene.ImageSize imageSize(Scene.ImageSize fallback) {
        return parsedScene != null ? parsedScene.image() : fallback;
    }

    /**
     * The scene to draw (validate() first): the file's, or the one the options describe, with the BRDF options
     * given applied to its material.
     */
    Scene scene(Scene.ImageSize defaultSize) {
        Scene s = parsedScene != null ? parsedScene : optionsScene(defaultSize);
        Scene.MaterialSpec m = s.material();
        // --terms replaces a scene's tolerance-chosen N
        Scene.MaterialSpec material = new Scene.MaterialSpec(m.patch(), brdf.apply(m.settings()),
                brdf.highestOrder != null ? null : m.orderTolerance(), m.pigmentation(), m.pigmentationOn(),
                m.diffuseWeight(), m.exposure());
        return new Scene(s.source(), s.image(), s.camera(), s.light(), s.shape(), material, s.mode());
    }

    /** The scene the options describe: the patch on a shape, the thesis' settings, an orbit camera, one light. */
    private Scene optionsScene(Scene.ImageSize size) {
        double phi = phiIDeg != null ? phiIDeg : patch.periodAzimuthDeg(DEFAULT_PATCH);
        double[] eye = new OrbitCamera(azimuthDeg, elevationDeg, distance, 0, 0, 0).eye();
        Scene.CameraSpec camera = new Scene.CameraSpec(eye, new double[3], new double[] {0, 1, 0},
                SceneSetup.DEFAULT_VERTICAL_FOV_DEG);
        Scene.LightSpec light = new Scene.LightSpec(vector(new LightDirection(thetaIDeg, phi)), "D65");
        Scene.ShapeSpec shapeSpec = new Scene.ShapeSpec(shape, null,
                TangentSource.projected(tangent.x(), tangent.y(), tangent.z()), SnakeMesh.RidgeDirection.ALONG_BODY,
                Scene.Transform.identity());
        Scene.PigmentationSpec pigment = pigmentation != null ? new Scene.PigmentationSpec(false, pigmentation)
                : shape == Scene.ShapeKind.SNAKE ? new Scene.PigmentationSpec(true, null) : Scene.PigmentationSpec.none();
        Scene.MaterialSpec material = new Scene.MaterialSpec(patch.spec(DEFAULT_PATCH), BrdfSettings.thesis(Variant.FLSS),
                null, pigment, pigment.present() && !noPigmentation, diffuseWeight, exposure);
        return new Scene(null, size, camera, light, shapeSpec, material,
                brdfMap ? DisplayMode.BRDF_MAP : DisplayMode.SURFACE);
    }

    private static double[] vector(LightDirection light) {
        var d = light.direction();
        return new double[] {d.x(), d.y(), d.z()};
    }

    /**
     * Reads the patch and the pigmentation image and builds the setup (validate() first); with a scene file, the
     * light, camera and display options given override the scene's; with --variant auto, the configuration its
     * calibration chose on this patch.
     */
    SceneSetup setup(Scene.ImageSize defaultSize, Reporter reporter) {
        SceneSetup s = Fabricator.fabricate(scene(defaultSize), reporter);
        if (parsedScene != null) {
            s = withOverrides(s);
        }
        if (!brdf.auto()) {
            return s;
        }
        AutoChoice choice = AutoVariant.choose(s.patch(), s.light().phiDeg(), s.settings(), brdf.maxDeltaE, reporter);
        System.out.println(choice.explanation());
        return s.withSettings(AutoVariant.settings(choice, s.settings().taylor().expansion()));
    }

    /** The scene's setup with the view options the command line gives in its place. */
    private SceneSetup withOverrides(SceneSetup s) {
        OrbitCamera c = s.camera();
        OrbitCamera camera = new OrbitCamera(given("--azimuth") ? azimuthDeg : c.azimuthDeg(),
                given("--elevation") ? elevationDeg : c.elevationDeg(), given("--distance") ? distance : c.distance(),
                c.targetX(), c.targetY(), c.targetZ());
        LightDirection light = new LightDirection(given("--theta-i") ? thetaIDeg : s.light().thetaDeg(),
                given("--phi-i") ? phiIDeg : s.light().phiDeg());
        return new SceneSetup(s.pipeline(), s.shape(), s.pigmentation(),
                given("--diffuse-weight") ? diffuseWeight : s.diffuseWeight(), s.settings(), camera, light,
                given("--exposure") ? exposure : s.exposure(), brdfMap ? DisplayMode.BRDF_MAP : s.mode(),
                s.pigmentationOn() && !noPigmentation, s.verticalFovDeg());
    }
}
