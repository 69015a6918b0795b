package diffract.scene;

import diffract.colour.MirrorNormalisation;
import diffract.geometry.SnakeMesh;
import diffract.geometry.SnakeSpecies;
import diffract.geometry.TangentSource;
import diffract.optics.BakedGrid;
import diffract.optics.BrdfSettings;
import diffract.optics.windows.CoherenceWindow;
import diffract.optics.settings.GainModel;
import diffract.optics.illumination.GainFactor;
import diffract.optics.illumination.IlluminationSettings;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.patches.Levelling;
import diffract.optics.settings.LightProfile;
import diffract.optics.illumination.LightSource;
import diffract.optics.LobeQuadrature;
import diffract.optics.Methods;
import diffract.optics.settings.OrderWeights;
import diffract.optics.patches.PatchCatalogue;
import diffract.optics.settings.PixelFilter;
import diffract.optics.settings.Polarisation;
import diffract.optics.patches.ProceduralPatches;
import diffract.optics.settings.Quantity;
import diffract.optics.RadiometricGain;
import diffract.optics.rigorous.RigorousSettings;
import diffract.optics.settings.SpectralSettings;
import diffract.optics.spectra.TaylorExpansion;
import diffract.optics.spectra.TaylorSettings;
import diffract.optics.settings.TermFormat;
import diffract.optics.Variant;
import diffract.optics.patches.ScanTiling;
import diffract.optics.windows.WindowPlacement;
import diffract.optics.spectra.WindowSettings;
import diffract.optics.rigorous.Resolution;
import diffract.util.UserInputException;

import java.io.IOException;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Reads a scene file ({@code docs/guide/scene-format.md}) into a checked {@link Scene}. Every problem is one
 * {@link UserInputException} line {@code FILE:LINE: key.path: what is wrong (and the fix)}: malformed JSON,
 * unknown keys (with the nearest known key), missing keys, wrong types, values out of range, files that do not
 * exist (paths are relative to the scene file's folder). Nothing else escapes, whatever the text.
 */
public final class SceneFile {
    /** The variants a scene can draw: the registered methods with a GPU shader. */
    static List<String> variants() {
        return Arrays.stream(Variant.values()).filter(Variant::runsOnGpu).map(Variant::label).toList();
    }
    static final List<String> EXPANSIONS = List.of("auto", "plain", "centred");
    static final List<String> TERM_FORMATS = List.of("rg32f", "rg16f", "rg8");
    static final List<String> MODES = List.of("surface", "brdfMap");
    static final List<String> GAIN_MODELS = java.util.Arrays.stream(GainModel.values()).map(GainModel::label).toList();
    /** "fresnel", the former key of "gain", took these (physical is stam). */
    static final List<String> FRESNEL_MODELS = List.of("physical", "stam", "thesis");
    static final List<String> NORMALISATIONS = Arrays.stream(MirrorNormalisation.values())
            .map(MirrorNormalisation::key).toList();
    /** {@code material.exposure}'s word for {@link RadiometricGain}. */
    static final String RADIOMETRIC = "radiometric";
    static final List<String> POLARISATIONS = Arrays.stream(Polarisation.values()).map(Polarisation::label).toList();
    static final List<String> ORDER_WEIGHTS = Arrays.stream(OrderWeights.values()).map(OrderWeights::label).toList();
    static final List<String> PIXEL_FILTERS = List.of("box", "point");
    static final List<String> LIGHT_PROFILES = List.of("disc", "gaussian");
    static final List<String> WINDOW_PLACEMENTS = List.of("averaged", "fixed", "local");
    /** The catalogue's names and their camelCase spellings. */
    static final List<String> PROCEDURAL_NAMES = proceduralNames();
    static final List<String> LEVELLING_NAMES = Arrays.stream(Levelling.values()).map(Levelling::label).toList();

    private SceneFile() {
    }

    private static List<String> proceduralNames() {
        List<String> names = new java.util.ArrayList<>();
        for (String name : PatchCatalogue.names()) {
            names.add(name);
            String camel = camelCase(name);
            if (!camel.equals(name)) {
                names.add(camel);
            }
        }
        return List.copyOf(names);
    }

    /** "elaphe-like" as "elapheLike". */
    static String camelCase(String name) {
        StringBuilder b = new StringBuilder();
        boolean upper = false;
        for (char c : name.toCharArray()) {
            if (c == '-') {
                upper = true;
            } else {
                b.append(upper ? Character.toUpperCase(c) : c);
                upper = false;
            }
        }
        return b.toString();
    }

    public static Scene load(Path file) {
        String text;
        try {
            text = StandardCharsets.UTF_8.newDecoder().decode(java.nio.ByteBuffer.wrap(Files.readAllBytes(file)))
                    .toString();
        } catch (CharacterCodingException e) {
            throw new UserInputException(file + ":1: the scene is not UTF-8 text; save it as UTF-8 JSON");
        } catch (IOException e) {
            throw new UserInputException("cannot read scene file " + file + ": "
                    + (e instanceof java.nio.file.NoSuchFileException ? "no such file" : e.getMessage()));
        }
        Path absolute = file.toAbsolutePath().normalize();
        return parse(text, file.toString(), absolute.getParent(), file);
    }

    /**
     * @param displayName   how messages name the file
     * @param baseDirectory where relative paths start
     * @param source        recorded in the scene
     */
    public static Scene parse(String text, String displayName, Path baseDirectory, Path source) {
        SceneObject.SceneSource where = new SceneObject.SceneSource(displayName, baseDirectory);
        JsonTree.Located tree;
        try {
            tree = JsonTree.parse(text);
        } catch (JsonTree.SyntaxError e) {
            throw SceneObject.problem(where, e.line, "(json)", e.getMessage());
        }
        SceneObject root = SceneObject.root(where, tree);
        Scene.ImageSize image = image(root);
        Scene.CameraSpec camera = camera(root.object("camera"));
        LightSource[] lightSource = new LightSource[1];
        Scene.LightSpec light = light(root.object("light"), lightSource);
        Scene.ShapeSpec shape = shape(root.object("shape"));
        Scene.MaterialSpec material = material(root.object("material"), lightSource[0], shape);
        Scene scene = new Scene(source, image, camera, light, shape, material,
                root.choice("mode", MODES, "surface").equals("brdfMap") ? DisplayMode.BRDF_MAP : DisplayMode.SURFACE,
                StageKeys.stage(root));
        root.finish();
        return scene;
    }

    private static Scene.ImageSize image(SceneObject root) {
        if (!root.has("image")) {
            return new Scene.ImageSize(640, 400);
        }
        SceneObject image = root.object("image");
        SceneObject.Range pixels = SceneObject.Range.closed(Scene.ImageSize.MIN_PX, Scene.ImageSize.MAX_PX);
        Scene.ImageSize size = new Scene.ImageSize(image.integer("width", pixels), image.integer("height", pixels));
        image.finish();
        return size;
    }

    private static Scene.CameraSpec camera(SceneObject camera) {
        double[] eye = camera.vector3("eye");
        double[] lookAt = camera.vector3("lookAt", new double[3]);
        double[] up = camera.has("up") ? camera.direction("up") : new double[] {0, 1, 0};
        double fov = camera.number("fieldOfViewDeg", SceneObject.Range.open(0, 180), 45);
        Scene.CameraSpec spec = new Scene.CameraSpec(eye, lookAt, up, fov);
        String problem = CameraManager.problem(spec);
        if (problem != null) {
            throw camera.problem("eye", problem);
        }
        String upProblem = CameraManager.upProblem(spec);
        if (upProblem != null) {
            throw camera.problem("up", upProblem);
        }
        camera.finish();
        return spec;
    }

    /**
     * The key light's direction and spectrum; its angular diameter ({@code angularDiameterDeg}, the sun's 0.53
     * degrees by default) and its profile (gaussian by default) go to {@code source[0]}, for the material's settings,
     * where every renderer reads them.
     */
    private static Scene.LightSpec light(SceneObject light, LightSource[] source) {
        double[] towards;
        if (light.has("direction")) {
            towards = light.direction("direction");
            if (light.has("thetaDeg") || light.has("phiDeg")) {
                throw light.problem(light.has("thetaDeg") ? "thetaDeg" : "phiDeg",
                        "give either \"direction\" or \"thetaDeg\"/\"phiDeg\", not both");
            }
        } else if (light.has("thetaDeg")) {
            double theta = Math.toRadians(light.number("thetaDeg", SceneObject.Range.any()));
            double phi = Math.toRadians(light.number("phiDeg", SceneObject.Range.any(), 0));
            towards = new double[] {Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta)};
        } else {
            throw SceneObject.problem(sourceOf(light), light.line(), light.keyPath("direction"),
                    "missing; add \"direction\": [x, y, z] (towards the light) or \"thetaDeg\" and \"phiDeg\"");
        }
        double thetaDeg = LightManager.thetaDeg(towards);
        if (thetaDeg > LightDirection.MAX_THETA_DEG + 1e-9) {
            throw light.problem(light.has("direction") ? "direction" : "thetaDeg", String.format(java.util.Locale.ROOT,
                    "the light is %.1f degrees from the +z axis; the viewer takes at most %.0f (light from the +z side)",
                    thetaDeg, LightDirection.MAX_THETA_DEG));
        }
        String spectrum = light.choice("spectrum", List.of("D65"), "D65");
        double sizeDeg = light.number("angularDiameterDeg", SceneObject.Range.closed(0, LightSource.MAX_DIAMETER_DEG),
                LightSource.SUN_DEG);
        source[0] = new LightSource(sizeDeg, LightProfile.parse(light.choice("profile", LIGHT_PROFILES, "disc")));
        light.finish();
        return new Scene.LightSpec(towards, spectrum);
    }

    private static SceneObject.SceneSource sourceOf(SceneObject object) {
        return object.source();
    }

    private static Scene.ShapeSpec shape(SceneObject shape) {
        List<String> kinds = java.util.Arrays.stream(Scene.ShapeKind.values()).map(Scene.ShapeKind::sceneName).toList();
        Scene.ShapeKind kind = Scene.ShapeKind.valueOf(shape.choice("kind", kinds).toUpperCase(java.util.Locale.ROOT));
        Path file = null;
        TangentSource tangents = null;
        SnakeMesh.RidgeDirection ridges = null;
        SnakeMesh.Pose pose = SnakeMesh.Pose.S_CURVE;
        StageSpec.ScalesSpec scales = null;
        StageSpec.NormalMapSpec normalMap = null;
        if (kind == Scene.ShapeKind.OBJ && shape.has("normalMap")) {
            normalMap = new StageSpec.NormalMapSpec(shape.existingFile("normalMap"));
        }
        if (kind == Scene.ShapeKind.SNAKE) {
            pose = StageKeys.pose(shape);
            scales = StageKeys.scales(shape);
        }
        if (kind == Scene.ShapeKind.OBJ) {
            file = shape.existingFile("file");
            tangents = tangents(shape, TangentSource.fromUvs(), true);
        } else if (kind == Scene.ShapeKind.SNAKE) {
            ridges = shape.choice("ridges", List.of("alongBody", "aroundBody"), "alongBody").equals("alongBody")
                    ? SnakeMesh.RidgeDirection.ALONG_BODY : SnakeMesh.RidgeDirection.AROUND_BODY;
        } else {
            tangents = tangents(shape, TangentSource.projected(1, 0, 0), false);
        }
        Scene.Transform transform = shape.has("transform") ? transform(shape.object("transform"))
                : Scene.Transform.identity();
        shape.finish();
        return new Scene.ShapeSpec(kind, file, tangents, ridges, transform, pose, scales, normalMap);
    }

    private static TangentSource tangents(SceneObject shape, TangentSource defaultSource, boolean obj) {
        if (!shape.has("tangents")) {
            return defaultSource;
        }
        JsonTree.Located node = shape.raw("tangents");
        String fix = obj ? "use \"explicit\" (tg lines), \"uv\" or {\"project\": [x, y, z]}"
                : "use {\"project\": [x, y, z]} (a world direction projected onto the surface)";
        if (node.value() instanceof String text && obj) {
            if (text.equals("explicit")) {
                return TangentSource.explicit();
            } else if (text.equals("uv")) {
                return TangentSource.fromUvs();
            }
            throw shape.problem("tangents", "unknown value \"" + text + "\""
                    + SceneObject.suggestion(text, List.of("explicit", "uv")) + "; " + fix);
        }
        if (node.value() instanceof Map) {
            SceneObject object = shape.child("tangents", node);
            double[] d = object.direction("project");
            object.finish();
            return TangentSource.projected(d[0], d[1], d[2]);
        }
        throw shape.problem("tangents", "must be " + (obj ? "a string or " : "") + "an object, got " + node.typeName()
                + "; " + fix);
    }

    private static Scene.Transform transform(SceneObject transform) {
        Scene.Transform t = new Scene.Transform(transform.vector3("translate", new double[3]),
                transform.vector3("rotateDeg", new double[3]),
                transform.number("scale", SceneObject.Range.above(0, 1000), 1.0));
        transform.finish();
        return t;
    }

    /** The scene key of each BRDF setting, for messages about a value the settings refuse. */
    static final Map<Quantity, String> MATERIAL_KEYS = Map.ofEntries(Map.entry(Quantity.VARIANT, "variant"),
            Map.entry(Quantity.HIGHEST_ORDER, "taylorTerms"), Map.entry(Quantity.ORDER_TOLERANCE, "tolerance"),
            Map.entry(Quantity.TAYLOR_TOLERANCE, "taylorTolerance"), Map.entry(Quantity.EXPANSION, "expansion"),
            Map.entry(Quantity.WINDOW_RADIUS, "windowRadius"), Map.entry(Quantity.PQ_REPLICAS, "pqReplicas"),
            Map.entry(Quantity.WINDOW_PLACEMENT, "window"),
            Map.entry(Quantity.LAMBDA_MIN, "lambdaMinNm"), Map.entry(Quantity.LAMBDA_MAX, "lambdaMaxNm"),
            Map.entry(Quantity.LAMBDA_STEP, "lambdaStepNm"), Map.entry(Quantity.COHERENCE_LENGTH, "coherenceLengthUm"),
            Map.entry(Quantity.REFRACTIVE_INDEX, "refractiveIndex"), Map.entry(Quantity.TERM_FORMAT, "termFormat"),
            Map.entry(Quantity.BAKED_SAMPLES, "bakedUvSamples"), Map.entry(Quantity.GAIN, "gain"),
            Map.entry(Quantity.PIXEL_FILTER, "pixelFilter"), Map.entry(Quantity.LOBE_QUADRATURE, "lobeQuadrature"),
            Map.entry(Quantity.SCAN_TILING, "skinUmPerTexcoord"), Map.entry(Quantity.HARMONICS, "harmonics"),
            Map.entry(Quantity.LAYERS, "layers"), Map.entry(Quantity.POLARISATION, "polarisation"),
            Map.entry(Quantity.ORDERS, "orders"));

    /**
     * A method: its label, its label with its parameter ({@code "label(of=inner)"}), or an object
     * {@code {"type": label, "of": inner}} whose {@code of} is a method again.
     */
    private static Variant variant(SceneObject parent, String key, JsonTree.Located node) {
        try {
            if (node.value() instanceof Map) {
                SceneObject o = parent.child(key, node);
                Variant type = Variant.parse(o.choice("type", variants()));
                Variant v = type;
                if (o.has("of")) {
                    Variant inner = variant(o, "of", o.raw("of"));
                    try {
                        v = type.of(inner);
                    } catch (InvalidSettingException e) {
                        throw o.problem("of", e.getMessage());
                    }
                }
                o.finish();
                return v;
            }
            if (node.value() instanceof String text) {
                String label = text.replaceFirst("\\(.*", "").trim();
                if (!variants().contains(label)) {
                    throw parent.problem(key, "unknown value \"" + text + "\"" + SceneObject.suggestion(label,
                            variants()) + "; use one of " + String.join(", ", variants())
                            + ", or {\"type\": ..., \"of\": ...}");
                }
                return Variant.parse(text);
            }
        } catch (InvalidSettingException e) {
            throw parent.problem(key, e.getMessage());
        }
        throw parent.problem(key, "must be a method's label, with its parameter or as {\"type\": ..., \"of\": ...}, got "
                + node.typeName());
    }

    /**
     * The lobes method's knobs ({@link LobeQuadrature#KNOBS}) that the object names, the others at their defaults;
     * each value is checked by the quadrature.
     */
    private static LobeQuadrature lobeQuadrature(SceneObject knobs) {
        Map<String, Double> given = new LinkedHashMap<>();
        for (String knob : LobeQuadrature.KNOBS) {
            if (knobs.has(knob)) {
                given.put(knob, knobs.number(knob, SceneObject.Range.any()));
            }
        }
        knobs.finish();
        return LobeQuadrature.DEFAULT.withKnobs(given);
    }

    private static Scene.MaterialSpec material(SceneObject material, LightSource lightSource,
                                                Scene.ShapeSpec shape) {
        Scene.PatchSpec patch = patch(material.object("patch"));
        BrdfSettings.Builder b = BrdfSettings.builder(material.has("variant")
                ? variant(material, "variant", material.raw("variant")) : Methods.Role.FILTERING.method());
        boolean radiometric = radiometric(material);
        Double tolerance = null;
        try {
            if (material.has("tolerance")) {
                if (material.has("taylorTerms")) {
                    throw material.problem("taylorTerms", "give either \"taylorTerms\" or \"tolerance\", not both");
                }
                tolerance = material.number("tolerance", SceneObject.Range.open(0, 1));
            } else {
                b.highestOrder(material.integer("taylorTerms",
                        SceneObject.Range.closed(0, TaylorSettings.MAX_HIGHEST_ORDER), 30));
            }
            b.taylorTolerance(material.number("taylorTolerance", SceneObject.Range.closed(0, 1), 0));
            b.expansion(TaylorExpansion.valueOf(material.choice("expansion", EXPANSIONS, "auto")
                    .toUpperCase(Locale.ROOT)));
            SceneObject.Range visible = SceneObject.Range.closed(SpectralSettings.LOWEST_NM, SpectralSettings.HIGHEST_NM);
            double lambdaMin = material.number("lambdaMinNm", visible, SpectralSettings.LAMBDA_MIN_NM);
            double lambdaMax = material.number("lambdaMaxNm", visible, SpectralSettings.LAMBDA_MAX_NM);
            if (!(lambdaMax > lambdaMin)) {
                throw material.problem(material.has("lambdaMaxNm") ? "lambdaMaxNm" : "lambdaMinNm",
                        "lambdaMaxNm must be greater than lambdaMinNm, got " + SceneObject.format(lambdaMin) + " and "
                                + SceneObject.format(lambdaMax));
            }
            MirrorNormalisation normalisation = MirrorNormalisation.valueOf(material.choice("normalisation",
                    NORMALISATIONS, radiometric ? "energy" : "peak").toUpperCase(Locale.ROOT));
            if (radiometric && normalisation != MirrorNormalisation.ENERGY) {
                throw material.problem("normalisation", "must be \"energy\" with \"exposure\": \"radiometric\" (under"
                        + " \"peak\" a mirror's lobes carry light that grows as lambda^2, and no single gain is"
                        + " radiometric)");
            }
            b.spectral(new SpectralSettings(lambdaMin, lambdaMax, material.number("lambdaStepNm",
                    SceneObject.Range.above(0, SpectralSettings.MAX_STEP_NM), 5), normalisation));
            windowRadius(material, b);
            b.pqReplicas(material.integer("pqReplicas", SceneObject.Range.closed(0, WindowSettings.MAX_PQ_REPLICAS), 0));
            WindowPlacement placement = WindowPlacement.parse(material.choice("window", WINDOW_PLACEMENTS, "averaged"));
            b.windowPlacement(placement);
            // the scan's columns lie along the mesh's tangent: along v on a snake whose ridges run along the body
            double[] tiling = material.pair("skinUmPerTexcoord",
                    SceneObject.Range.above(0, ScanTiling.MAX_UM_PER_TEXCOORD));
            b.scanTiling(new ScanTiling(tiling[0], tiling[1], shape.ridges() == SnakeMesh.RidgeDirection.ALONG_BODY));
            if (placement == WindowPlacement.LOCAL && tiling[0] == 0) {
                throw material.problem("window", "\"local\" needs \"skinUmPerTexcoord\": the micrometres of skin one"
                        + " unit of the mesh's texture coordinates spans, a number or [u, v]");
            }
            b.illumination(illumination(material).withLight(lightSource).withGain(gain(material))
                    .withPixelFilter(PixelFilter.parse(material.choice("pixelFilter", PIXEL_FILTERS, "box"))));
            b.termFormat(TermFormat.valueOf(material.choice("termFormat", TERM_FORMATS, "rg32f")
                    .toUpperCase(Locale.ROOT)));
            SceneObject.Range samples = SceneObject.Range.closed(0, BakedGrid.MAX_SAMPLES);
            b.bakedSamples(material.integer("bakedUvSamples", samples, 0), material.integer("bakedWSamples", samples, 0));
            if (material.has("lobeQuadrature")) {
                b.lobes(lobeQuadrature(material.object("lobeQuadrature")));
            }
            b.rigorous(rigorous(material));
        } catch (InvalidSettingException e) {
            throw material.problem(MATERIAL_KEYS.getOrDefault(e.quantity(), "variant"), e.getMessage());
        }
        Scene.PigmentationSpec pigmentation = pigmentation(material);
        boolean pigmentationOn = material.bool("pigmentationOn", pigmentation.present());
        if (pigmentationOn && !pigmentation.present()) {
            throw material.problem("pigmentationOn", "is true but \"pigmentation\" is \"none\"; give "
                    + "\"pigmentation\": \"procedural\" or {\"file\": \"IMAGE\"}");
        }
        double diffuseWeight = material.number("diffuseWeight", SceneObject.Range.closed(0, 1), 0.2);
        BrdfSettings settings;
        try {
            settings = b.build(); // checks the groups together: the local window's method
        } catch (InvalidSettingException e) {
            throw material.problem(MATERIAL_KEYS.getOrDefault(e.quantity(), "variant"), e.getMessage());
        }
        double exposure = radiometric ? RadiometricGain.of(settings)
                : material.number("exposure", SceneObject.Range.above(0, 1e6), 10);
        material.finish();
        return new Scene.MaterialSpec(patch, settings, tolerance, pigmentation, pigmentationOn, diffuseWeight, exposure);
    }

    /**
     * Whether {@code material.exposure} is "radiometric": the gain of {@link RadiometricGain} (pi R_0 / Omega),
     * which puts the structural colour in the pigment's units; any other word is refused.
     */
    private static boolean radiometric(SceneObject material) {
        if (material.has("exposure") && material.raw("exposure").value() instanceof String text) {
            if (!text.equals(RADIOMETRIC)) {
                throw material.problem("exposure", "must be a number above 0 or \"" + RADIOMETRIC + "\", got \""
                        + text + "\"");
            }
            return true;
        }
        return false;
    }

    /** A whole number of texels, or "auto" (the radius per axis from sigma_f). */
    private static void windowRadius(SceneObject material, BrdfSettings.Builder b) {
        if (material.has("windowRadius") && material.raw("windowRadius").value() instanceof String text) {
            if (!text.equals("auto")) {
                throw material.problem("windowRadius", "must be a whole number in [0, " + WindowSettings.MAX_RADIUS
                        + "] or \"auto\", got \"" + text + "\"");
            }
            b.automaticWindowRadius(true);
            return;
        }
        b.windowRadius(material.integer("windowRadius", SceneObject.Range.closed(0, WindowSettings.MAX_RADIUS), 1));
    }

    /** "gain", or its former key "fresnel" (not both); Rayleigh-Rice's by default. */
    private static GainModel gain(SceneObject material) {
        if (material.has("fresnel")) {
            if (material.has("gain")) {
                throw material.problem("fresnel", "is the former name of \"gain\": give one of them");
            }
            return GainModel.parse(material.choice("fresnel", FRESNEL_MODELS, "stam"));
        }
        return GainModel.parse(material.choice("gain", GAIN_MODELS, GainModel.RAYLEIGH_RICE.label()));
    }

    /**
     * Maxwell's equations' settings: "orders" (whether the lobes method takes its orders from them), "harmonics" (a
     * whole number or "auto"), "layers", "layerExtrapolation" and "polarisation"; each at its default when absent.
     */
    private static RigorousSettings rigorous(SceneObject material) {
        Resolution r = Resolution.DEFAULT;
        int maxOrder = r.maxOrder();
        if (material.has("harmonics") && material.raw("harmonics").value() instanceof String text) {
            if (!text.equals("auto")) {
                throw material.problem("harmonics", "must be a whole number in [1, " + Resolution.MAX_ORDER
                        + "] or \"auto\", got \"" + text + "\"");
            }
        } else if (material.has("harmonics")) {
            maxOrder = material.integer("harmonics", SceneObject.Range.closed(1, Resolution.MAX_ORDER));
        }
        int layers = material.integer("layers", SceneObject.Range.closed(1, Resolution.MAX_LAYERS), r.layers());
        boolean extrapolate = material.bool("layerExtrapolation", r.extrapolate());
        if (extrapolate && layers % 2 != 0) {
            throw material.problem("layers", "the staircase is extrapolated from L / 2 and L layers: give an even"
                    + " number, or \"layerExtrapolation\": false; got " + layers);
        }
        Polarisation polarisation = Polarisation.parse(material.choice("polarisation", POLARISATIONS,
                RigorousSettings.DEFAULT.polarisation().label()));
        OrderWeights orders = OrderWeights.parse(material.choice("orders", ORDER_WEIGHTS,
                RigorousSettings.DEFAULT.orders().label()));
        return new RigorousSettings(new Resolution(maxOrder, layers, extrapolate), polarisation, orders);
    }

    /** The coherence length (or the thesis' sigma_s, a quarter of it) and the complex refractive index n + i k. */
    private static IlluminationSettings illumination(SceneObject material) {
        SceneObject.Range coherence = SceneObject.Range.above(0, IlluminationSettings.MAX_COHERENCE_LENGTH_UM);
        double coherenceLengthUm;
        if (material.has("sigmaSpatialUm")) {
            if (material.has("coherenceLengthUm")) {
                throw material.problem("sigmaSpatialUm", "give either \"coherenceLengthUm\" or \"sigmaSpatialUm\" "
                        + "(a quarter of it), not both");
            }
            coherenceLengthUm = 4 * material.number("sigmaSpatialUm",
                    SceneObject.Range.above(0, IlluminationSettings.MAX_COHERENCE_LENGTH_UM / 4));
        } else {
            coherenceLengthUm = material.number("coherenceLengthUm", coherence, CoherenceWindow.COHERENCE_LENGTH_UM);
        }
        double n = material.number("refractiveIndex", SceneObject.Range.closed(1, IlluminationSettings.MAX_REFRACTIVE_INDEX),
                GainFactor.KERATIN_REFRACTIVE_INDEX);
        double k = material.number("extinction", SceneObject.Range.closed(0, IlluminationSettings.MAX_EXTINCTION), 0);
        return IlluminationSettings.ofCoherenceLength(coherenceLengthUm, n)
                .withMaterial(new diffract.optics.rigorous.ComplexIndex(n, k));
    }

    private static Scene.PigmentationSpec pigmentation(SceneObject material) {
        if (!material.has("pigmentation")) {
            return Scene.PigmentationSpec.none();
        }
        JsonTree.Located node = material.raw("pigmentation");
        if (node.value() instanceof String text) {
            if (text.equals("none")) {
                return Scene.PigmentationSpec.none();
            } else if (text.equals("procedural")) {
                return Scene.PigmentationSpec.proceduralPattern();
            } else if (StageKeys.speciesNames().contains(text)) {
                return Scene.PigmentationSpec.ofSpecies(SnakeSpecies.fromSceneName(text));
            }
            List<String> known = new java.util.ArrayList<>(List.of("none", "procedural"));
            known.addAll(StageKeys.speciesNames());
            throw material.problem("pigmentation", "unknown value \"" + text + "\""
                    + SceneObject.suggestion(text, known)
                    + "; use \"none\", \"procedural\", a species (\"" + String.join("\", \"", StageKeys.speciesNames())
                    + "\") or {\"file\": \"IMAGE\"}");
        }
        if (node.value() instanceof Map) {
            SceneObject object = material.child("pigmentation", node);
            Path file = object.existingFile("file");
            object.finish();
            return Scene.PigmentationSpec.imageFile(file);
        }
        throw material.problem("pigmentation", "must be \"none\", \"procedural\" or {\"file\": \"IMAGE\"}, got "
                + node.typeName());
    }

    /** A multi-channel file's channel: its title (a string) or its index (a whole number). */
    private static String channel(SceneObject patch) {
        JsonTree.Located node = patch.raw("channel");
        if (node.value() instanceof String title && !title.isBlank()) {
            return title;
        }
        if (node.value() instanceof Double index && index >= 0 && index == Math.rint(index) && index < 1e9) {
            return Long.toString(index.longValue());
        }
        throw patch.problem("channel", "must be a channel's title (a string) or its index (a whole number >= 0), got "
                + (node.value() instanceof Double d ? SceneObject.format(d) : node.typeName()));
    }

    private static Scene.PatchSpec patch(SceneObject patch) {
        if (patch.has("file")) {
            Path file = patch.existingFile("file");
            if (patch.has("procedural")) {
                throw patch.problem("procedural", "give either \"file\" or \"procedural\", not both");
            }
            Double maxHeight = patch.has("maxHeightUm") ? patch.number("maxHeightUm", SceneObject.Range.positive()) : null;
            Double pixelSize = patch.has("pixelSizeUm") ? patch.number("pixelSizeUm", SceneObject.Range.positive()) : null;
            String channel = patch.has("channel") ? channel(patch) : null;
            Levelling levelling = patch.has("level") ? Levelling.fromLabel(patch.choice("level", LEVELLING_NAMES))
                    : null; // the file format's default
            patch.finish();
            return new Scene.FilePatch(file, maxHeight, pixelSize, channel, levelling);
        }
        if (!patch.has("procedural")) {
            throw SceneObject.problem(patch.source(), patch.line(), patch.keyPath("procedural"), "missing; add "
                    + "\"file\": \"HEIGHTFIELD\" or \"procedural\": one of \"" + String.join("\", \"",
                    PatchCatalogue.names()) + "\"");
        }
        String name = patch.choice("procedural", PROCEDURAL_NAMES);
        PatchCatalogue.Entry entry = PatchCatalogue.named(name);
        ProceduralPatches.Spec d = entry.spec();
        ProceduralPatches.Kind kind = d.kind();
        double period = patch.number("periodUm", SceneObject.Range.above(0, 100), d.periodUm());
        double height = patch.number("heightUm", SceneObject.Range.closed(0, 10), d.heightUm());
        int periods = patch.integer("periods", SceneObject.Range.closed(1, 256), d.periods());
        int samplesPerPeriod = d.samplesPerPeriod();
        int rows = d.rows();
        int size = d.sizePx();
        double roughness = d.roughnessUm();
        long seed = d.seed();
        if (kind.isGrating()) {
            samplesPerPeriod = patch.integer("samplesPerPeriod", SceneObject.Range.closed(2, 256), samplesPerPeriod);
            rows = patch.integer("rows", SceneObject.Range.closed(1, 1024), rows);
            if ((long) samplesPerPeriod * periods > 4096) {
                throw patch.problem(patch.has("periods") ? "periods" : "samplesPerPeriod", "periods x samplesPerPeriod "
                        + "must be at most 4096 columns, got " + samplesPerPeriod * periods);
            }
        } else {
            size = patch.integer("sizePx", SceneObject.Range.closed(16, 2048), size);
            if (size % 16 != 0) {
                throw patch.problem("sizePx", "must be a multiple of 16, got " + size);
            }
            seed = patch.wholeNumber("seed", seed);
            if (kind == ProceduralPatches.Kind.XENOPELTIS_LIKE) {
                roughness = patch.number("roughnessUm", SceneObject.Range.closed(0, 1), roughness);
            }
        }
        patch.finish();
        return new Scene.ProceduralPatch(entry.name(), new ProceduralPatches.Spec(kind, period, height, periods,
                samplesPerPeriod, rows, size, roughness, seed));
    }
}
