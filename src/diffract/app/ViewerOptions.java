package diffract.app;

import diffract.geometry.PigmentationTexture;
import diffract.jrtr.Shape;
import diffract.optics.BrdfSettings;
import diffract.optics.GainFactor;
import diffract.optics.HeightField;
import diffract.optics.SyntheticPatches;
import diffract.optics.TaylorEvaluation;
import diffract.optics.Variant;
import diffract.optics.io.HeightFieldReader;
import diffract.optics.io.SamplingCheck;
import diffract.precompute.Precomputation;
import diffract.scene.Fabricator;
import diffract.scene.Scene;
import diffract.scene.SceneFile;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import diffract.viewer.DisplayMode;
import diffract.viewer.LightDirection;
import diffract.viewer.OrbitCamera;
import diffract.viewer.PigmentationImage;
import diffract.viewer.TermSource;
import diffract.viewer.ViewerSetup;
import diffract.viewer.ViewerShapes;
import picocli.CommandLine.Option;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * What {@code view} and {@code render} show, as options: they fill a {@link ViewerSetup}. With a SCENE file the
 * {@link Fabricator} fills it from the file instead, and the options given on the command line override what they
 * name (variant, terms, lambda step, window, coherence, light, camera angles, exposure, mode, pigmentation switch,
 * diffuse weight); options that name what only the scene may say (the patch, the shape) are refused.
 */
final class ViewerOptions {
    /** What a scene file describes by itself: these options cannot be combined with one. */
    static final List<String> SCENE_ONLY = List.of("--patch", "--max-height", "--pixel-size", "--synthetic", "--shape",
            "--tangent", "--pigmentation");

    @Parameters(index = "0", arity = "0..1", paramLabel = "SCENE",
            description = "A scene file (JSON, docs/scene-format.md), e.g. assets/scenes/snake-elaphe.json; options "
                    + "given as well override what they name.")
    Path scene;

    @Spec(Spec.Target.MIXEE)
    CommandSpec mixee;

    /** The scene read by validate() and built by setup(), when a SCENE was given. */
    private Scene parsedScene;
    private Fabricator.Fabricated fabricated;

    @Option(names = "--patch", paramLabel = "FILE",
            description = "Height field: PNG/BMP/TIFF (8 or 16 bit grey), text matrix or Gwyddion .gsf.")
    Path patch;

    @Option(names = "--max-height", paramLabel = "UM", description = "Height of the brightest grey value (images).")
    Double maxHeightUm;

    @Option(names = "--pixel-size", paramLabel = "UM", description = "Pixel size dH in micrometres (images and text).")
    Double pixelSizeUm;

    @Option(names = "--synthetic", paramLabel = "KIND",
            description = "A patch made by code instead of --patch: elaphe-like (default) or blazed (d = 2.5 um, 65 um wide).")
    String synthetic;

    @Option(names = "--shape", defaultValue = "sphere", paramLabel = "S",
            description = "sphere, plane, cylinder or snake (procedural, with corn-snake pigmentation; default ${DEFAULT-VALUE}).")
    String shape;

    @Option(names = "--tangent", defaultValue = "1,0,0", paramLabel = "X,Y,Z",
            description = "World direction of the patch's x axis (columns) on the shape, projected onto each surface point (default ${DEFAULT-VALUE}).")
    String tangent;

    @Option(names = "--pigmentation", paramLabel = "IMAGE",
            description = "Pigment colours over the shape's texcoords (sRGB image); P toggles it.")
    Path pigmentation;

    @Option(names = "--no-pigmentation", description = "Start with the pigmentation off (structural colour only; P toggles it).")
    boolean noPigmentation;

    @Option(names = "--diffuse-weight", defaultValue = "0.2", paramLabel = "W",
            description = "w_d: pigment mixed in as ambient light (default ${DEFAULT-VALUE}).")
    double diffuseWeight;

    @Option(names = "--variant", defaultValue = "flss", paramLabel = "V",
            description = "flss, nmm, pq, baked, or auto: the cheapest configuration (float32 terms) whose measured "
                    + "error on the patch meets --max-delta-e (default ${DEFAULT-VALUE}).")
    String variant;

    @Option(names = "--max-delta-e", paramLabel = "DE",
            description = "With --variant auto: the accuracy target, mean CIEDE2000 against the reference over the lit pixels.")
    Double maxDeltaE;

    @Option(names = "--terms", defaultValue = "30", paramLabel = "N", description = "Highest Taylor order N (default ${DEFAULT-VALUE}).")
    int highestOrder;

    @Option(names = "--lambda-step", defaultValue = "5", paramLabel = "NM", description = "Wavelength step (default ${DEFAULT-VALUE}).")
    double lambdaStepNm;

    @Option(names = "--window-radius", defaultValue = "1", paramLabel = "R", description = "Window of (2R+1)^2 texels (default ${DEFAULT-VALUE}).")
    int windowRadius;

    @Option(names = "--coherence-length", defaultValue = "65", paramLabel = "UM", description = "4 sigma_s (default ${DEFAULT-VALUE}).")
    double coherenceLengthUm;

    @Option(names = "--taylor-tolerance", defaultValue = "0", paramLabel = "EPS",
            description = "Stop each lookup's Taylor loop once the Lagrange bound is <= EPS; 0 = always --terms (default ${DEFAULT-VALUE}).")
    double taylorTolerance;

    @Option(names = "--auto-window", description = "Window radius per axis from sigma_f (99.73 % of the window's weight) instead of --window-radius.")
    boolean automaticWindow;

    @Option(names = "--theta-i", defaultValue = "30", paramLabel = "DEG", description = "Light polar angle from the world z axis (default ${DEFAULT-VALUE}).")
    double thetaIDeg;

    @Option(names = "--phi-i", paramLabel = "DEG",
            description = "Light azimuth from the world x axis (default: 90 for elaphe-like, whose period runs along y; else 0).")
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

    /** Everything checked that needs no file and no GL: bad usage fails before any work. */
    void validate() {
        if (scene != null) {
            for (String option : SCENE_ONLY) {
                if (given(option)) {
                    throw new UserInputException(option + " cannot be combined with a SCENE: the scene file says "
                            + "that (edit " + scene + ", or leave the SCENE out)");
                }
            }
            parsedScene = SceneFile.load(scene); // a bad scene fails here, before any OpenGL
        }
        if (patch != null && synthetic != null) {
            throw new UserInputException("give --patch FILE or --synthetic KIND, not both");
        }
        if (synthetic != null) {
            syntheticPatch(synthetic); // names a known kind
        }
        ViewerShapes.Kind.parse(shape);
        parseTangent(tangent);
        settings();
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

    BrdfSettings settings() {
        if (highestOrder < 0 || highestOrder > diffract.viewer.ViewerController.MAX_HIGHEST_ORDER) {
            throw new UserInputException("--terms must be between 0 and "
                    + diffract.viewer.ViewerController.MAX_HIGHEST_ORDER + ", got " + highestOrder);
        }
        if (!(coherenceLengthUm > 0)) {
            throw new UserInputException("--coherence-length must be > 0 um, got " + coherenceLengthUm);
        }
        boolean auto = auto();
        AutoVariant.checkOptions(auto, maxDeltaE, null);
        // auto resolves to a concrete variant once the patch is read (resolveAuto); FLSS stands in until then
        Variant v = auto ? Variant.FLSS : Variant.parse(variant);
        if (v == Variant.REFERENCE) {
            throw new UserInputException("the viewer draws on the GPU: use --variant flss, nmm or pq (or baked) "
                    + "(the reference runs on the CPU: ./diffract brdfmap)");
        }
        return new BrdfSettings(v, highestOrder, windowRadius, BrdfSettings.LAMBDA_MIN_NM, BrdfSettings.LAMBDA_MAX_NM,
                lambdaStepNm, coherenceLengthUm / 4.0, GainFactor.SNAKE_SKIN_REFRACTIVE_INDEX, 0)
                .withTaylorTolerance(taylorTolerance).withAutomaticWindowRadius(automaticWindow);
    }

    private boolean auto() {
        return variant.trim().equalsIgnoreCase(AutoVariant.NAME);
    }

    /**
     * With {@code --variant auto}: the cheapest measured configuration on this patch that meets --max-delta-e,
     * among those with float32 terms (the viewer's storage); otherwise the settings unchanged.
     */
    private BrdfSettings resolveAuto(HeightField meanSubtracted, double phiIDeg, BrdfSettings settings, Reporter reporter) {
        if (!auto()) {
            return settings;
        }
        // rendered on the thesis' series, the path the calibration measured (not the automatic expansion)
        return AutoVariant.choose(meanSubtracted, phiIDeg, settings, maxDeltaE, reporter,
                r -> r.config().textureFormat().equals(diffract.bench.SweepPlan.EXACT_FORMAT)).chosen().config()
                .settings().withExpansion(TaylorEvaluation.Mode.PLAIN);
    }

    /** The snake's procedural corn-snake pigmentation is the same every run. */
    static final long PIGMENT_SEED = 2014;

    /** Whether the user gave {@code option} on the command line (not just its default). */
    boolean given(String option) {
        return mixee != null && mixee.commandLine() != null && mixee.commandLine().getParseResult() != null
                && mixee.commandLine().getParseResult().hasMatchedOption(option);
    }

    /** Reads the patch and the pigmentation image (or the scene) and builds the setup (validate() first). */
    ViewerSetup setup(Reporter reporter) {
        if (scene != null) {
            fabricated = Fabricator.fabricate(parsedScene != null ? parsedScene : SceneFile.load(scene), reporter);
            return withOverrides(fabricated.setup(), reporter);
        }
        HeightField field;
        String name;
        if (patch != null) {
            field = HeightFieldReader.load(patch, maxHeightUm, pixelSizeUm, reporter);
            name = patch.getFileName().toString();
        } else {
            name = synthetic == null ? "elaphe-like" : synthetic.toLowerCase(Locale.ROOT);
            field = syntheticPatch(name);
        }
        field = field.meanSubtracted();
        BrdfSettings settings = settings();
        SamplingCheck.warnAboutAliasing(field, settings.lambdaMinNm(), settings.lambdaMaxNm(), reporter);
        Shape mesh = ViewerShapes.Kind.parse(shape).build(parseTangent(tangent));
        BufferedImage pigment = pigmentation != null ? PigmentationImage.read(pigmentation)
                : ViewerShapes.Kind.parse(shape) == ViewerShapes.Kind.SNAKE
                ? new PigmentationTexture(PigmentationTexture.Parameters.defaults(PIGMENT_SEED)).image(256, 2048) : null;
        double phi = phiIDeg != null ? phiIDeg : name.equals("elaphe-like") ? 90 : 0;
        settings = resolveAuto(field, phi, settings, reporter);
        return new ViewerSetup(field, name, mesh, pigment, diffuseWeight, settings,
                new OrbitCamera(azimuthDeg, elevationDeg, distance, 0, 0, 0), new LightDirection(thetaIDeg, phi),
                exposure, brdfMap ? DisplayMode.BRDF_MAP : DisplayMode.SURFACE, pigment != null && !noPigmentation);
    }

    /** The scene's setup with what the command line names in its place. */
    private ViewerSetup withOverrides(ViewerSetup s, Reporter reporter) {
        BrdfSettings settings = s.settings();
        if (given("--variant")) {
            settings = settings.withVariant(settings().variant());
        }
        if (given("--terms")) {
            settings = settings.withHighestOrder(highestOrder);
        }
        if (given("--lambda-step")) {
            settings = settings.withLambdaStepNm(lambdaStepNm);
        }
        if (given("--window-radius")) {
            settings = settings.withWindowRadius(windowRadius);
        }
        if (given("--coherence-length")) {
            settings = settings.withSigmaSpatialUm(coherenceLengthUm / 4.0);
        }
        if (given("--taylor-tolerance")) {
            settings = settings.withTaylorTolerance(taylorTolerance);
        }
        if (given("--auto-window")) {
            settings = settings.withAutomaticWindowRadius(true);
        }
        settings = resolveAuto(s.patch(), given("--phi-i") ? phiIDeg : s.light().phiDeg(), settings, reporter);
        OrbitCamera c = s.camera();
        OrbitCamera camera = new OrbitCamera(given("--azimuth") ? azimuthDeg : c.azimuthDeg(),
                given("--elevation") ? elevationDeg : c.elevationDeg(), given("--distance") ? distance : c.distance(),
                c.targetX(), c.targetY(), c.targetZ());
        LightDirection light = new LightDirection(given("--theta-i") ? thetaIDeg : s.light().thetaDeg(),
                given("--phi-i") ? phiIDeg : s.light().phiDeg());
        return new ViewerSetup(s.patch(), s.patchName(), s.shape(), s.pigmentation(),
                given("--diffuse-weight") ? diffuseWeight : s.diffuseWeight(), settings, camera, light,
                given("--exposure") ? exposure : s.exposure(), brdfMap ? DisplayMode.BRDF_MAP : s.mode(),
                s.pigmentationOn() && !noPigmentation, s.verticalFovDeg());
    }

    /**
     * The picture's (or window's) size: {@code --size} when given, else the scene's image size, else the command's
     * default {@code sizeOption}.
     */
    int[] size(String sizeOption, boolean sizeGiven) {
        if (fabricated != null && !sizeGiven) {
            return new int[] {fabricated.image().width(), fabricated.image().height()};
        }
        return parseSize(sizeOption);
    }

    /** Terms from the user cache (computed and stored on first use), keyed by patch content and N. */
    TermSource termSource(ViewerSetup setup) {
        if (fabricated != null) {
            return fabricated.terms();
        }
        return (n, reporter) -> Precomputation.cached(new Precomputation.Request(setup.patch(), setup.patchName(),
                maxHeightUm, n, null, setup.settings().lambdaMinNm()), reporter);
    }

    static HeightField syntheticPatch(String kind) {
        switch (kind.toLowerCase(Locale.ROOT)) {
            case "elaphe-like":
                return SyntheticPatches.elapheLike();
            case "blazed":
                return SyntheticPatches.blazed(2.5, 0.2, 25, 26, 16);
            default:
                throw new UserInputException("unknown --synthetic '" + kind + "': use elaphe-like or blazed");
        }
    }

    static double[] parseTangent(String text) {
        String[] parts = text.split(",");
        if (parts.length == 3) {
            try {
                double[] v = {Double.parseDouble(parts[0].trim()), Double.parseDouble(parts[1].trim()),
                    Double.parseDouble(parts[2].trim())};
                if (Double.isFinite(v[0] + v[1] + v[2]) && v[0] * v[0] + v[1] * v[1] + v[2] * v[2] > 1e-12) {
                    return v;
                }
            } catch (NumberFormatException ignored) {
                // falls through to the message below
            }
        }
        throw new UserInputException("--tangent must be a non-zero vector X,Y,Z, got '" + text + "'");
    }

    /** WxH or S (square); 16..4096 pixels per side. */
    static int[] parseSize(String text) {
        String[] parts = text.toLowerCase(Locale.ROOT).split("x");
        try {
            int w = Integer.parseInt(parts[0].trim());
            int h = parts.length == 1 ? w : Integer.parseInt(parts[1].trim());
            if (parts.length <= 2 && w >= 16 && h >= 16 && w <= 4096 && h <= 4096) {
                return new int[] {w, h};
            }
        } catch (NumberFormatException ignored) {
            // falls through to the message below
        }
        throw new UserInputException("--size must be WxH (or S) with 16..4096 pixels per side, got '" + text + "'");
    }
}
