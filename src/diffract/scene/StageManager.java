package diffract.scene;

import diffract.colour.Srgb;
import diffract.geometry.ScaleLattice;
import diffract.geometry.ScaledSkin;
import diffract.geometry.SnakeMesh;
import diffract.geometry.SnakeSpecies;
import diffract.lighting.ClearSky;
import diffract.lighting.Environment;
import diffract.lighting.LatLongMap;
import diffract.lighting.RadianceHdr;
import diffract.render.Stage;
import diffract.util.UserInputException;

import java.awt.image.BufferedImage;

/**
 * The stage's constants manager: turns the scene's scales, environment, ground and tone mapping into a
 * {@link Stage} (the scale frame map baked, the environment reduced to extended lights and irradiance), and paints
 * a species' pigmentation on the snake's scales.
 */
final class StageManager {
    /** The clear sky is made at this size: its light varies slowly, the median cut and the harmonics need no more. */
    static final int SKY_WIDTH = 256;

    private StageManager() {
    }

    static Stage stage(Scene scene) {
        StageSpec spec = scene.stage();
        Stage.ScaleFrames frames = null;
        StageSpec.ScalesSpec scales = scene.shape().scales();
        if (scales != null) {
            ScaledSkin skin = skin(scene, scales.lattice(), scales.species());
            frames = new Stage.ScaleFrames(scales.mapWidthPx(), scales.mapHeightPx(),
                    skin.frameMap(scales.mapWidthPx(), scales.mapHeightPx()));
        }
        if (scene.shape().normalMap() != null) {
            java.awt.image.BufferedImage image = diffract.geometry.NormalMapImage.read(scene.shape().normalMap().file());
            frames = new Stage.ScaleFrames(image.getWidth(), image.getHeight(),
                    diffract.geometry.NormalMapImage.frameMap(image));
        }
        double[] groundLinear = spec.ground() == null ? new double[] {0.2, 0.2, 0.2}
                : new double[] {Srgb.decode(spec.ground().albedoSrgb()[0]),
                    Srgb.decode(spec.ground().albedoSrgb()[1]), Srgb.decode(spec.ground().albedoSrgb()[2])};
        Environment environment = null;
        if (spec.environment() != null) {
            StageSpec.EnvironmentSpec e = spec.environment();
            LatLongMap map = e.file() != null ? RadianceHdr.read(e.file())
                    : ClearSky.map(unit(scene.light().towardsLight()), e.skyIrradianceRatio(), groundLinear, SKY_WIDTH,
                    SKY_WIDTH / 2);
            map = map.scaled(e.scale());
            if (e.rotateDeg() != 0) {
                map = map.rotatedAboutY(e.rotateDeg());
            }
            environment = new Environment(map, Integer.numberOfTrailingZeros(e.lights()));
        }
        Stage.Ground ground = spec.ground() == null ? null
                : new Stage.Ground(groundLinear, spec.ground().mottle(), spec.ground().shadows(), 2048,
                        scene.material().settings().illumination().light().angularDiameterDeg());
        return new Stage(frames, environment, ground, spec.toneMapping());
    }

    /** The species' pigmentation on the snake's scales (the shape's lattice, or the species' own when it has none). */
    static BufferedImage speciesPigment(Scene scene, SnakeSpecies species) {
        if (scene.shape().kind() != Scene.ShapeKind.SNAKE) {
            throw new UserInputException(scene.source() + ": material.pigmentation \"" + species.sceneName()
                    + "\" is painted on a snake's scales; use it with \"shape\": {\"kind\": \"snake\"}");
        }
        StageSpec.ScalesSpec scales = scene.shape().scales();
        ScaleLattice.Parameters lattice = scales != null ? scales.lattice() : species.scales();
        ScaledSkin skin = skin(scene, lattice, species);
        int width = scales != null ? scales.mapWidthPx() : 512;
        int height = scales != null ? scales.mapHeightPx() : 4096;
        return skin.pigmentImage(species.pattern(skin.lattice(), MaterialManager.PIGMENT_SEED), width, height);
    }

    private static ScaledSkin skin(Scene scene, ScaleLattice.Parameters lattice, SnakeSpecies species) {
        SnakeMesh snake = SnakeMesh.generate(ShapeManager.snakeParameters(scene.shape()));
        return new ScaledSkin(new ScaleLattice(lattice), snake.profile(), scene.shape().ridges());
    }

    private static double[] unit(double[] v) {
        double l = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        return new double[] {v[0] / l, v[1] / l, v[2] / l};
    }
}
