package diffract.scene;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import diffract.geometry.SnakeMesh;
import diffract.geometry.TangentSource;
import diffract.optics.BrdfSettings;
import diffract.optics.GpuTableSettings;
import diffract.optics.illumination.IlluminationSettings;
import diffract.optics.LobeQuadrature;
import diffract.optics.patches.ProceduralPatches;
import diffract.optics.RadiometricGain;
import diffract.optics.rigorous.RigorousSettings;
import diffract.optics.settings.SpectralSettings;
import diffract.optics.spectra.TaylorSettings;
import diffract.optics.spectra.WindowSettings;
import diffract.optics.rigorous.Resolution;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Writes a {@link Scene} as the scene file {@link SceneFile} reads ({@code docs/guide/scene-format.md}): every key spelled
 * out, defaults included, so that the file says all that the picture depends on; paths absolute, so that it reads
 * the same from any folder. Reading it back gives the same scene, and writing that again the same text.
 */
public final class SceneWriter {
    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private SceneWriter() {
    }

    /** The scene file's text (JSON, two-space indents, a final newline). */
    public static String json(Scene scene) {
        try {
            return JSON.writeValueAsString(tree(scene)) + "\n";
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("a scene of numbers, strings and lists is always JSON", e);
        }
    }

    /** The scene as nested maps and lists, in the order the format documents them. */
    static Map<String, Object> tree(Scene scene) {
        Map<String, Object> root = new LinkedHashMap<>();
        Map<String, Object> image = new LinkedHashMap<>();
        image.put("width", scene.image().width());
        image.put("height", scene.image().height());
        root.put("image", image);
        root.put("mode", scene.mode() == DisplayMode.BRDF_MAP ? "brdfMap" : "surface");
        root.put("camera", camera(scene.camera()));
        root.put("light", light(scene.light(), scene.material().settings().illumination()));
        root.put("shape", shape(scene.shape()));
        root.put("material", material(scene.material()));
        StageSpec stage = scene.stage();
        if (stage.environment() != null) {
            root.put("environment", environment(stage.environment()));
        }
        if (stage.ground() != null) {
            Map<String, Object> ground = new LinkedHashMap<>();
            ground.put("albedoSrgb", list(stage.ground().albedoSrgb()));
            ground.put("mottle", stage.ground().mottle());
            ground.put("shadows", stage.ground().shadows());
            root.put("ground", ground);
        }
        Map<String, Object> tone = new LinkedHashMap<>();
        tone.put("operator", stage.toneMapping().operator().sceneName());
        tone.put("exposureStops", stage.toneMapping().exposureStops());
        tone.put("whiteLuminance", stage.toneMapping().whiteLuminance());
        root.put("toneMapping", tone);
        return root;
    }

    private static Map<String, Object> camera(Scene.CameraSpec c) {
        Map<String, Object> camera = new LinkedHashMap<>();
        camera.put("eye", list(c.eye()));
        camera.put("lookAt", list(c.lookAt()));
        camera.put("up", list(c.up()));
        camera.put("fieldOfViewDeg", c.fieldOfViewDeg());
        return camera;
    }

    /** The key light: its direction, spectrum, and the size and profile the material's settings hold. */
    private static Map<String, Object> light(Scene.LightSpec l, IlluminationSettings illumination) {
        Map<String, Object> light = new LinkedHashMap<>();
        light.put("direction", list(l.towardsLight()));
        light.put("spectrum", l.spectrum());
        light.put("angularDiameterDeg", illumination.light().angularDiameterDeg());
        light.put("profile", illumination.light().profile().label());
        return light;
    }

    private static Map<String, Object> shape(Scene.ShapeSpec s) {
        Map<String, Object> shape = new LinkedHashMap<>();
        shape.put("kind", s.kind().sceneName());
        if (s.kind() == Scene.ShapeKind.OBJ) {
            shape.put("file", path(s.file()));
            if (s.normalMap() != null) {
                shape.put("normalMap", path(s.normalMap().file()));
            }
        }
        if (s.kind() == Scene.ShapeKind.SNAKE) {
            shape.put("ridges", s.ridges() == SnakeMesh.RidgeDirection.ALONG_BODY ? "alongBody" : "aroundBody");
            shape.put("pose", s.pose() == SnakeMesh.Pose.COILED ? "coiled" : "sCurve");
            if (s.scales() != null) {
                shape.put("scales", scales(s.scales()));
            }
        } else {
            shape.put("tangents", tangents(s.tangents()));
        }
        Map<String, Object> transform = new LinkedHashMap<>();
        transform.put("translate", list(s.transform().translate()));
        transform.put("rotateDeg", list(s.transform().rotateDeg()));
        transform.put("scale", s.transform().scale());
        shape.put("transform", transform);
        return shape;
    }

    private static Object tangents(TangentSource t) {
        if (t instanceof TangentSource.Explicit) {
            return "explicit";
        }
        if (t instanceof TangentSource.FromUvs) {
            return "uv";
        }
        TangentSource.Projected p = (TangentSource.Projected) t;
        return Map.of("project", List.of(p.x(), p.y(), p.z()));
    }

    private static Map<String, Object> scales(StageSpec.ScalesSpec s) {
        Map<String, Object> scales = new LinkedHashMap<>();
        scales.put("species", s.species().sceneName());
        var p = s.lattice();
        scales.put("dorsalScaleRows", p.dorsalRows());
        scales.put("ventralScales", p.ventralScales());
        scales.put("ventralFraction", p.ventralFraction());
        scales.put("domeSlopeDeg", p.domeSlopeDeg());
        scales.put("tiltDeg", p.tiltDeg());
        scales.put("tiltJitterDeg", p.tiltJitterDeg());
        scales.put("yawJitterDeg", p.yawJitterDeg());
        scales.put("overlap", p.overlap());
        scales.put("seed", p.seed());
        scales.put("mapWidthPx", s.mapWidthPx());
        scales.put("mapHeightPx", s.mapHeightPx());
        return scales;
    }

    private static Map<String, Object> material(Scene.MaterialSpec m) {
        BrdfSettings s = m.settings();
        Map<String, Object> material = new LinkedHashMap<>();
        material.put("patch", patch(m.patch()));
        material.put("variant", s.variant().spec());
        TaylorSettings taylor = s.taylor();
        if (m.orderTolerance() != null) {
            material.put("tolerance", m.orderTolerance());
        } else {
            material.put("taylorTerms", taylor.highestOrder());
        }
        material.put("taylorTolerance", taylor.tolerance());
        material.put("expansion", taylor.expansion().name().toLowerCase(Locale.ROOT));
        SpectralSettings spectral = s.spectral();
        material.put("lambdaMinNm", spectral.lambdaMinNm());
        material.put("lambdaMaxNm", spectral.lambdaMaxNm());
        material.put("lambdaStepNm", spectral.lambdaStepNm());
        material.put("normalisation", spectral.normalisation().key());
        WindowSettings window = s.window();
        material.put("windowRadius", window.automatic() ? "auto" : (Object) window.radius());
        material.put("pqReplicas", window.pqReplicas());
        material.put("window", window.placement().label());
        if (window.tiling().umPerTexcoordU() > 0) {
            material.put("skinUmPerTexcoord", List.of(window.tiling().umPerTexcoordU(),
                    window.tiling().umPerTexcoordV()));
        }
        IlluminationSettings illumination = s.illumination();
        material.put("coherenceLengthUm", illumination.coherenceLengthUm());
        material.put("refractiveIndex", illumination.refractiveIndex());
        material.put("extinction", illumination.extinction());
        material.put("gain", illumination.gain().label());
        material.put("pixelFilter", illumination.pixelFilter().label());
        GpuTableSettings gpu = s.gpu();
        material.put("termFormat", gpu.termFormat().name().toLowerCase(Locale.ROOT));
        material.put("bakedUvSamples", gpu.bakedUvSamples());
        material.put("bakedWSamples", gpu.bakedWSamples());
        material.put("lobeQuadrature", lobeQuadrature(s.lobes()));
        RigorousSettings rigorous = s.rigorous();
        material.put("orders", rigorous.orders().label());
        Resolution resolution = rigorous.resolution();
        material.put("harmonics", resolution.maxOrder() == 0 ? "auto" : (Object) resolution.maxOrder());
        material.put("layers", resolution.layers());
        material.put("layerExtrapolation", resolution.extrapolate());
        material.put("polarisation", rigorous.polarisation().label());
        material.put("pigmentation", pigmentation(m.pigmentation()));
        material.put("pigmentationOn", m.pigmentationOn());
        material.put("diffuseWeight", m.diffuseWeight());
        // the radiometric gain is a function of the settings: the word keeps it one when they change
        material.put("exposure", m.exposure() == RadiometricGain.of(s) ? SceneFile.RADIOMETRIC : (Object) m.exposure());
        return material;
    }

    /** The knobs by name, the count of light nodes as a whole number. */
    private static Map<String, Object> lobeQuadrature(LobeQuadrature q) {
        Map<String, Object> knobs = new LinkedHashMap<>(q.knobs());
        knobs.put("lightNodes", q.lightNodes());
        return knobs;
    }

    private static Object pigmentation(Scene.PigmentationSpec p) {
        if (p.procedural()) {
            return "procedural";
        }
        if (p.species() != null) {
            return p.species().sceneName();
        }
        if (p.file() != null) {
            return Map.of("file", path(p.file()));
        }
        return "none";
    }

    private static Map<String, Object> patch(Scene.PatchSpec spec) {
        Map<String, Object> patch = new LinkedHashMap<>();
        if (spec instanceof Scene.FilePatch f) {
            patch.put("file", path(f.file()));
            if (f.maxHeightUm() != null) {
                patch.put("maxHeightUm", f.maxHeightUm());
            }
            if (f.pixelSizeUm() != null) {
                patch.put("pixelSizeUm", f.pixelSizeUm());
            }
            if (f.channel() != null) {
                patch.put("channel", f.channel());
            }
            if (f.levelling() != null) {
                patch.put("level", f.levelling().label());
            }
            return patch;
        }
        Scene.ProceduralPatch p = (Scene.ProceduralPatch) spec;
        ProceduralPatches.Spec d = p.spec();
        patch.put("procedural", p.name());
        patch.put("periodUm", d.periodUm());
        patch.put("heightUm", d.heightUm());
        patch.put("periods", d.periods());
        if (d.kind().isGrating()) {
            patch.put("samplesPerPeriod", d.samplesPerPeriod());
            patch.put("rows", d.rows());
        } else {
            patch.put("sizePx", d.sizePx());
            patch.put("seed", d.seed());
            if (d.kind() == ProceduralPatches.Kind.XENOPELTIS_LIKE) {
                patch.put("roughnessUm", d.roughnessUm());
            }
        }
        return patch;
    }

    private static Map<String, Object> environment(StageSpec.EnvironmentSpec e) {
        Map<String, Object> environment = new LinkedHashMap<>();
        if (e.file() != null) {
            environment.put("file", path(e.file()));
        } else {
            environment.put("sky", Map.of("irradianceRatio", e.skyIrradianceRatio()));
        }
        environment.put("scale", e.scale());
        environment.put("rotateDeg", e.rotateDeg());
        environment.put("lights", e.lights());
        return environment;
    }

    private static List<Double> list(double[] v) {
        return java.util.Arrays.stream(v).boxed().toList();
    }

    private static String path(Path p) {
        return p.toAbsolutePath().normalize().toString();
    }
}
