package diffract.app;

import diffract.app.options.BrdfOptions;
import diffract.app.options.OptionNames;
import diffract.app.options.OptionTypes;
import diffract.app.options.PatchOptions;
import diffract.bench.AutoChoice;
import diffract.bench.AutoVariant;
import diffract.geometry.SnakeMesh;
import diffract.geometry.SnakeSpecies;
import diffract.geometry.TangentSource;
import diffract.optics.BrdfSettings;
import diffract.optics.Methods;
import diffract.optics.Variant;
import diffract.optics.illumination.LightSource;
import diffract.optics.settings.PixelFilter;
import diffract.optics.settings.Quantity;
import diffract.optics.windows.WindowPlacement;
import diffract.render.DiffractionMaterials;
import diffract.render.DiffractionShaders;
import diffract.scene.DisplayMode;
import diffract.scene.Fabricator;
import diffract.scene.LightDirection;
import diffract.scene.OrbitCamera;
import diffract.scene.Scene;
import diffract.scene.SceneFile;
import diffract.scene.SceneOverrides;
import diffract.scene.SceneSetup;
import diffract.scene.SceneWriter;
import diffract.scene.SkinOverrides;
import diffract.scene.StageSpec;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.TypeConversionException;

import java.nio.file.Path;
import java.util.List;

/**
 * What {@code view} and {@code render} show, as options. A scene comes from a SCENE file, from the shipped
 * {@code assets/scenes/viewer-snake.json} with {@code --shape snake}, or from the options alone (a sphere, a plane or
 * a cylinder under the thesis' settings); the {@link Fabricator} builds each alike. Beside a scene the options given
 * override what they name (patch, BRDF settings, light, camera angles, exposure, mode, species, skin, tangent,
 * pigmentation, diffuse weight); only {@code --shape} is refused beside a SCENE, which says its own shape.
 */
final class ViewerOptions {
    @Parameters(index = "0", arity = "0..1", paramLabel = "SCENE", descriptionKey = "scene") Path scene;

    @Spec(Spec.Target.MIXEE)
    CommandSpec mixee;

    @Option(names = "--dump-scene") boolean dumpScene;

    @Mixin PatchOptions patch;
    @Mixin BrdfOptions brdf;

    @ArgGroup(exclusive = false, validate = false, heading = "Shape and skin:%n")
    Surface surface = new Surface();

    @ArgGroup(exclusive = false, validate = false, heading = "Light, camera and picture:%n")
    View view = new View();

    /** What the patch covers, and the pigment over it. */
    static final class Surface {
        @Option(names = "--shape", defaultValue = "sphere", paramLabel = "S", converter = ShapeConverter.class,
                completionCandidates = OptionTypes.ShapeNames.class)
        Scene.ShapeKind shape = Scene.ShapeKind.SPHERE;

        @Option(names = "--species", defaultValue = "elapheGuttata", paramLabel = "NAME",
                converter = SpeciesConverter.class)
        SnakeSpecies species = SnakeSpecies.ELAPHE_GUTTATA;

        @Option(names = "--smooth-skin") boolean smoothSkin;

        @Option(names = "--tangent", defaultValue = "1,0,0", paramLabel = "X,Y,Z",
                converter = OptionTypes.Vector3.Converter.class)
        OptionTypes.Vector3 tangent = new OptionTypes.Vector3(1, 0, 0);

        @Option(names = "--pigmentation", paramLabel = "IMAGE") Path pigmentation;

        @Option(names = "--no-pigmentation") boolean noPigmentation;

        @Option(names = "--diffuse-weight", defaultValue = "0.2", paramLabel = "W") double diffuseWeight = 0.2;
    }

    /** The light, the orbit camera, what is shown and at what size. */
    static final class View {
        @Option(names = "--theta-i", defaultValue = "30", paramLabel = "DEG") double thetaIDeg = 30;

        @Option(names = "--phi-i", paramLabel = "DEG") Double phiIDeg;

        @Option(names = "--azimuth", defaultValue = "0", paramLabel = "DEG") double azimuthDeg;

        @Option(names = "--elevation", defaultValue = "20", paramLabel = "DEG") double elevationDeg = 20;

        @Option(names = "--distance", defaultValue = "3.5", paramLabel = "D") double distance = 3.5;

        @Option(names = "--exposure", defaultValue = "400", paramLabel = "E|auto",
                converter = OptionTypes.Exposure.Converter.class)
        OptionTypes.Exposure exposure = new OptionTypes.Exposure(400.0);

        @Option(names = "--brdf-map") boolean brdfMap;

        @Option(names = "--size", paramLabel = "WxH", converter = OptionTypes.ImageSize.Converter.class)
        OptionTypes.ImageSize size;
    }

    /** The exposure of a shape without a scene, and where --exposure auto starts. */
    static final double DEFAULT_EXPOSURE = 400;

    /** The patch a command line without --patch or --synthetic shows. */
    static final String DEFAULT_PATCH = "elaphe-like";

    /** What a scene file describes by itself: these options cannot be combined with one. */
    static final List<String> SCENE_ONLY = List.of("--shape");

    /** The scene read by validate(). */
    private Scene parsedScene;

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

    /** The species by its scene-file name (elapheGuttata, xenopeltisUnicolor). */
    static final class SpeciesConverter implements ITypeConverter<SnakeSpecies> {
        @Override
        public SnakeSpecies convert(String text) {
            try {
                return SnakeSpecies.fromSceneName(text.trim());
            } catch (IllegalArgumentException e) {
                throw new TypeConversionException("unknown species '" + text + "': use elapheGuttata or xenopeltisUnicolor");
            }
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
        } else if (surface.shape == Scene.ShapeKind.SNAKE) {
            parsedScene = shippedSnake();
        }
        Scene.ShapeKind shape = parsedScene != null ? parsedScene.shape().kind() : surface.shape;
        if (shape != Scene.ShapeKind.SNAKE && (given("--species") || surface.smoothSkin)) {
            throw new UserInputException((surface.smoothSkin ? "--smooth-skin" : "--species") + " dresses a snake, "
                    + "and the " + (scene != null ? "scene " + scene + " shows a " : "shape is a ") + shape.sceneName()
                    + (scene != null ? "" : ": add --shape snake"));
        }
        patch.validate();
        brdf.validate();
        if (!brdf.variantOr(defaultVariant).runsOnGpu()) {
            throw new UserInputException(DiffractionShaders.cpuOnly(brdf.variantOr(defaultVariant))
                    + " (./diffract brdfmap draws it)");
        }
        BrdfSettings checked = brdf.apply(parsedScene != null ? parsedScene.material().settings() : defaults());
        if (checked.window().placement() == WindowPlacement.LOCAL && !checked.window().tiling().given()) {
            throw new UserInputException(OptionNames.of(Quantity.SCAN_TILING) + ": "
                    + DiffractionMaterials.LOCAL_NEEDS_A_TILING);
        }
        if (!(view.distance >= OrbitCamera.MIN_DISTANCE && view.distance <= OrbitCamera.MAX_DISTANCE)) {
            throw new UserInputException("--distance must be in [" + OrbitCamera.MIN_DISTANCE + ", "
                    + OrbitCamera.MAX_DISTANCE + "], got " + view.distance);
        }
        if (!(view.thetaIDeg >= 0 && view.thetaIDeg <= LightDirection.MAX_THETA_DEG)) {
            throw new UserInputException("--theta-i must be in [0, " + LightDirection.MAX_THETA_DEG_TEXT
                    + "] degrees, got " + view.thetaIDeg);
        }
        if (!Double.isFinite(view.azimuthDeg) || !Double.isFinite(view.elevationDeg)
                || (view.phiIDeg != null && !Double.isFinite(view.phiIDeg))) {
            throw new UserInputException("angles must be finite numbers");
        }
    }

    /** Whether the user gave {@code option} on the command line (not just its default). */
    boolean given(String option) {
        return mixee != null && mixee.commandLine() != null && mixee.commandLine().getParseResult() != null
                && mixee.commandLine().getParseResult().hasMatchedOption(option);
    }

    /** {@code --size}, else the scene file's image size, else the command's {@code fallback} (validate() first). */
    Scene.ImageSize imageSize(Scene.ImageSize fallback) {
        if (view.size != null) {
            return new Scene.ImageSize(view.size.width(), view.size.height());
        }
        return parsedScene != null ? parsedScene.image() : fallback;
    }

    /**
     * The scene to draw (validate() first): the file's, or the one the options describe, with the BRDF options
     * given applied to its material.
     */
    Scene scene(Scene.ImageSize defaultSize) {
        Scene base = parsedScene != null ? withImage(parsedScene, imageSize(defaultSize)) : optionsScene(defaultSize);
        Scene s = sceneOverrides().applyTo(skinOverrides().applyTo(base));
        Scene.MaterialSpec m = s.material();
        // --terms replaces a scene's tolerance-chosen N; --patch or --synthetic the scene's patch
        Scene.PatchSpec patchSpec = parsedScene != null && patch.given() ? patch.spec(DEFAULT_PATCH) : m.patch();
        Scene.MaterialSpec material = new Scene.MaterialSpec(patchSpec, brdf.apply(m.settings()),
                brdf.highestOrderGiven() ? null : m.orderTolerance(), m.pigmentation(), m.pigmentationOn(),
                m.diffuseWeight(), m.exposure());
        return s.withMaterial(material);
    }

    /** What the options given say of the shape and its skin. */
    private SkinOverrides skinOverrides() {
        OptionTypes.Vector3 t = surface.tangent;
        return new SkinOverrides(given("--species") ? surface.species : null, surface.smoothSkin,
                given("--tangent") ? new double[] {t.x(), t.y(), t.z()} : null, surface.pigmentation);
    }

    /**
     * What {@code --shape snake} shows: the shipped scene, drawn by the command's own method unless --variant names
     * one.
     */
    private Scene shippedSnake() {
        Scene snake = ShippedScenes.load(ShippedScenes.VIEWER_SNAKE);
        Scene.MaterialSpec m = snake.material();
        return snake.withMaterial(m.withSettings(m.settings().with(b -> b.variant(defaultVariant))));
    }

    /** What the options given beside a scene replace in it. */
    private SceneOverrides sceneOverrides() {
        return new SceneOverrides(given("--azimuth") ? view.azimuthDeg : null,
                given("--elevation") ? view.elevationDeg : null, given("--distance") ? view.distance : null,
                given("--theta-i") ? view.thetaIDeg : null, given("--phi-i") ? view.phiIDeg : null,
                given("--exposure") && !view.exposure.automatic() ? view.exposure.factor() : null,
                given("--diffuse-weight") ? surface.diffuseWeight : null,
                surface.noPigmentation, view.brdfMap);
    }

    private static Scene withImage(Scene s, Scene.ImageSize image) {
        return new Scene(s.source(), image, s.camera(), s.light(), s.shape(), s.material(), s.mode(), s.stage());
    }

    /**
     * With --dump-scene: the scene these options describe printed as a scene file (validate() first), and true;
     * the command then draws nothing.
     */
    boolean dumpedScene(Scene.ImageSize defaultSize) {
        if (!dumpScene) {
            return false;
        }
        if (exposureAuto()) {
            throw new UserInputException("--dump-scene writes a scene of one exposure; --exposure auto measures the "
                    + "picture: run without --dump-scene to see its choice (it says 'auto exposure E'), then give it");
        }
        if (brdf.auto()) {
            throw new UserInputException("--dump-scene writes a scene of one method; --variant auto chooses its "
                    + "method by measuring the patch: run without --dump-scene to see its choice, then give it");
        }
        System.out.print(SceneWriter.json(scene(imageSize(defaultSize))));
        return true;
    }

    /**
     * The scene the options describe without a scene file: the patch on a sphere, a plane or a cylinder, the thesis'
     * settings, an orbit camera about the origin, one light (the shape's skin and pigment come from
     * {@link #skinOverrides}, the camera's and light's given values from {@link #sceneOverrides}).
     */
    private Scene optionsScene(Scene.ImageSize size) {
        double phi = view.phiIDeg != null ? view.phiIDeg : patch.periodAzimuthDeg(DEFAULT_PATCH);
        double distance = given("--distance") ? view.distance : defaultDistance;
        double[] eye = new OrbitCamera(view.azimuthDeg, view.elevationDeg, distance, 0, 0, 0).eye();
        Scene.CameraSpec camera = new Scene.CameraSpec(eye, new double[3], new double[] {0, 1, 0},
                SceneSetup.DEFAULT_VERTICAL_FOV_DEG);
        Scene.LightSpec light = new Scene.LightSpec(vector(new LightDirection(view.thetaIDeg, phi)), "D65");
        Scene.ShapeSpec shapeSpec = new Scene.ShapeSpec(surface.shape, null, TangentSource.projected(1, 0, 0),
                SnakeMesh.RidgeDirection.ALONG_BODY, Scene.Transform.identity(), SnakeMesh.Pose.S_CURVE, null, null);
        Scene.MaterialSpec material = new Scene.MaterialSpec(patch.spec(DEFAULT_PATCH), defaults(), null,
                Scene.PigmentationSpec.none(), false, surface.diffuseWeight,
                given("--exposure") && !view.exposure.automatic() ? view.exposure.factor() : defaultExposure);
        return new Scene(null, size, camera, light, shapeSpec, material, DisplayMode.SURFACE, StageSpec.none());
    }

    /**
     * The settings of a scene the options describe, as a scene file's defaults: the command's variant (the lobes
     * method for stills, its baked table for the viewer) at the thesis' 65 um coherence under the sun (0.53
     * degrees), each pixel its footprint's average, the Fresnel term counted once.
     */
    BrdfSettings defaults() {
        return BrdfSettings.thesis(defaultVariant).with(b -> b.lightSizeDeg(defaultLightDeg)
                .pixelFilter(PixelFilter.BOX));
    }

    /** The light's size, the camera's distance and the exposure of a shape without a scene, where none is given. */
    private double defaultLightDeg = LightSource.SUN_DEG;
    private double defaultDistance = DEFAULT_DISTANCE;
    private double defaultExposure = DEFAULT_EXPOSURE;

    /** The camera's distance of a shape without a scene. */
    static final double DEFAULT_DISTANCE = 3.5;
    /** The viewer's first look: a soft light beside the camera (as the staged scenes' key light), in degrees. */
    static final double FIRST_LOOK_LIGHT_DEG = 15;
    /** ... the camera closer, the sphere filling most of the window. */
    static final double FIRST_LOOK_DISTANCE = 2.3;
    /** ... and the exposure that shows its orders unclipped (auto's choice, 1.9e3, rounded down). */
    static final double FIRST_LOOK_EXPOSURE = 1600;

    /**
     * {@code view}'s first look at a shape without a scene, where the options do not say otherwise: under the sun a
     * grating's orders are as thin as the sun, and the sphere showed 0.5 % of its window in saturated structural
     * colour; under a 15-degree soft light, closer, 5.9 % (docs/guide/viewer.md). Before {@link #validate}.
     */
    void firstLook() {
        defaultLightDeg = FIRST_LOOK_LIGHT_DEG;
        defaultDistance = FIRST_LOOK_DISTANCE;
        defaultExposure = FIRST_LOOK_EXPOSURE;
    }

    /** The variant when none is given: {@link Variant#LOBES} unless the command says otherwise. */
    private Variant defaultVariant = Methods.Role.FILTERING.method();

    /** Sets the variant drawn when the options give none (before {@link #validate}). */
    void defaultVariant(Variant v) {
        defaultVariant = v;
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
        if (brdf.auto()) {
            AutoChoice choice = AutoVariant.choose(s.patch(), s.light().phiDeg(), s.settings(), brdf.maxDeltaE,
                    reporter);
            System.out.println(choice.explanation());
            s = s.withSettings(AutoVariant.settings(choice, s.settings().taylor().expansion()));
        }
        if (exposureAuto()) {
            Scene.ImageSize size = imageSize(defaultSize);
            StructuralProbe probe = StructuralProbe.of(s, size.width(), size.height(), reporter);
            double exposure = probe.autoExposure(s.exposure());
            reporter.info(String.format(java.util.Locale.ROOT, "auto exposure %.4g (the scene's %.4g)%s", exposure,
                    s.exposure(), probe.brightY() > 0 ? "" : ": no structural colour to expose, the scene's kept"));
            s = s.withExposure(exposure);
        }
        return s;
    }

    /**
     * {@code current} with another shape, as the viewer's frame switches it: the snake is the shipped viewer snake's
     * scene (its scales, pigment and camera) with the current settings; a sphere, plane or cylinder the options' shape
     * under the current light, the orbit camera's start, no pigment and no stage.
     */
    Scene withShape(Scene current, Scene.ShapeKind kind) {
        Scene.MaterialSpec m = current.material();
        if (kind == Scene.ShapeKind.SNAKE) {
            Scene snake = ShippedScenes.load(ShippedScenes.VIEWER_SNAKE);
            Scene.MaterialSpec s = snake.material();
            return snake.withMaterial(new Scene.MaterialSpec(m.patch(), m.settings(), null, s.pigmentation(),
                    s.pigmentationOn(), s.diffuseWeight(), s.exposure()));
        }
        double[] eye = new OrbitCamera(0, 20, 3.5, 0, 0, 0).eye();
        Scene.CameraSpec camera = new Scene.CameraSpec(eye, new double[3], new double[] {0, 1, 0},
                SceneSetup.DEFAULT_VERTICAL_FOV_DEG);
        Scene.ShapeSpec shapeSpec = new Scene.ShapeSpec(kind, null, TangentSource.projected(1, 0, 0),
                SnakeMesh.RidgeDirection.ALONG_BODY, Scene.Transform.identity(), SnakeMesh.Pose.S_CURVE, null, null);
        Scene.MaterialSpec material = new Scene.MaterialSpec(m.patch(), m.settings(), null,
                Scene.PigmentationSpec.none(), false, m.diffuseWeight(), m.exposure());
        return new Scene(null, current.image(), camera, current.light(), shapeSpec, material, current.mode(),
                StageSpec.none());
    }

    /** What the scene shows (validate() first). */
    Scene.ShapeKind shapeKind() {
        return parsedScene != null ? parsedScene.shape().kind() : surface.shape;
    }

    /** Whether --exposure auto was given: the exposure that maps the picture's bright structural colour to 1. */
    boolean exposureAuto() {
        return given("--exposure") && view.exposure.automatic();
    }
}
