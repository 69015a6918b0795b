package diffract.scene;

import diffract.colour.ToneMapping;
import diffract.geometry.ScaleLattice;
import diffract.geometry.SnakeMesh;
import diffract.geometry.SnakeSpecies;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Reads the scene keys of the stage and the scales ({@code docs/guide/scene-format.md}): "environment", "ground",
 * "toneMapping" at the top level; "pose" and "scales" of a snake shape.
 */
final class StageKeys {
    static final List<String> POSES = List.of("sCurve", "coiled");
    static final List<String> OPERATORS = List.of("clip", "reinhard", "aces");

    private StageKeys() {
    }

    static List<String> speciesNames() {
        List<String> names = new ArrayList<>();
        for (SnakeSpecies s : SnakeSpecies.values()) {
            names.add(s.sceneName());
        }
        return names;
    }

    static StageSpec stage(SceneObject root) {
        StageSpec.EnvironmentSpec environment = root.has("environment") ? environment(root.object("environment")) : null;
        StageSpec.GroundSpec ground = root.has("ground") ? ground(root.object("ground")) : null;
        ToneMapping tone = root.has("toneMapping") ? toneMapping(root.object("toneMapping")) : ToneMapping.clip();
        return new StageSpec(environment, ground, tone);
    }

    private static StageSpec.EnvironmentSpec environment(SceneObject env) {
        Path file = null;
        double ratio = 0.25;
        if (env.has("file")) {
            file = env.existingFile("file");
            if (env.has("sky")) {
                throw env.problem("sky", "give either \"file\" or \"sky\", not both");
            }
        } else if (env.has("sky")) {
            SceneObject sky = env.object("sky");
            ratio = sky.number("irradianceRatio", SceneObject.Range.closed(0, 10), ratio);
            sky.finish();
        } else {
            throw SceneObject.problem(env.source(), env.line(), env.keyPath("sky"),
                    "missing; add \"sky\": {} (a clear sky around the key light) or \"file\": \"MAP.hdr\"");
        }
        double scale = env.number("scale", SceneObject.Range.closed(0, 1e6), 1);
        double rotate = env.number("rotateDeg", SceneObject.Range.any(), 0);
        int lights = env.integer("lights", SceneObject.Range.closed(1, diffract.render.Stage.MAX_ENVIRONMENT_LIGHTS), 8);
        if (Integer.bitCount(lights) != 1) {
            throw env.problem("lights", "must be a power of two (the median cut halves regions), got " + lights
                    + "; use 1, 2, 4, 8 or 16");
        }
        env.finish();
        return new StageSpec.EnvironmentSpec(file, scale, rotate, ratio, lights);
    }

    private static StageSpec.GroundSpec ground(SceneObject ground) {
        double[] albedo = ground.vector3("albedoSrgb", new double[] {0.42, 0.36, 0.29});
        for (double c : albedo) {
            if (!(c >= 0 && c <= 1)) {
                throw ground.problem("albedoSrgb", "must hold three numbers in [0, 1] (display sRGB)");
            }
        }
        double mottle = ground.number("mottle", SceneObject.Range.closed(0, 1), 0.3);
        boolean shadows = ground.bool("shadows", true);
        ground.finish();
        return new StageSpec.GroundSpec(albedo, mottle, shadows);
    }

    private static ToneMapping toneMapping(SceneObject tone) {
        ToneMapping.Operator op = ToneMapping.Operator.parse(tone.choice("operator", OPERATORS, "reinhard"));
        double stops = tone.number("exposureStops", SceneObject.Range.closed(-20, 20), 0);
        double white = tone.number("whiteLuminance", SceneObject.Range.above(0, 1e6), 4);
        tone.finish();
        return new ToneMapping(op, stops, white);
    }

    static SnakeMesh.Pose pose(SceneObject shape) {
        return shape.choice("pose", POSES, "sCurve").equals("coiled") ? SnakeMesh.Pose.COILED : SnakeMesh.Pose.S_CURVE;
    }

    static StageSpec.ScalesSpec scales(SceneObject shape) {
        if (!shape.has("scales")) {
            return null;
        }
        SceneObject s = shape.object("scales");
        SnakeSpecies species = SnakeSpecies.fromSceneName(s.choice("species", speciesNames()));
        ScaleLattice.Parameters d = species.scales();
        ScaleLattice.Parameters p = new ScaleLattice.Parameters(
                s.integer("dorsalScaleRows", SceneObject.Range.closed(5, 61), d.dorsalRows()),
                s.integer("ventralScales", SceneObject.Range.closed(20, 600), d.ventralScales()),
                s.number("ventralFraction", SceneObject.Range.closed(0.05, 0.45), d.ventralFraction()),
                s.number("domeSlopeDeg", SceneObject.Range.closed(0, 40), d.domeSlopeDeg()),
                s.number("tiltDeg", SceneObject.Range.closed(0, 30), d.tiltDeg()),
                s.number("tiltJitterDeg", SceneObject.Range.closed(0, 20), d.tiltJitterDeg()),
                s.number("yawJitterDeg", SceneObject.Range.closed(0, 30), d.yawJitterDeg()),
                s.number("overlap", SceneObject.Range.closed(1.15, 1.6), d.overlap()),
                s.wholeNumber("seed", d.seed()));
        int width = s.integer("mapWidthPx", SceneObject.Range.closed(64, 4096),
                StageSpec.ScalesSpec.DEFAULT_MAP_WIDTH_PX);
        int height = s.integer("mapHeightPx", SceneObject.Range.closed(256, 16384),
                StageSpec.ScalesSpec.DEFAULT_MAP_HEIGHT_PX);
        s.finish();
        return new StageSpec.ScalesSpec(species, p, width, height);
    }
}
