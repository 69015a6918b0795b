package diffract.scene;

import diffract.geometry.SnakeSpecies;
import diffract.geometry.TangentSource;

import java.nio.file.Path;

/**
 * What a command line says of a scene's shape and skin, applied to the scene as {@link SceneOverrides} applies the
 * camera and light: a snake's species (its scales, and its pigment where the scene paints a species'), a smooth skin
 * (no scales, the procedural corn-snake pattern in place of a species' pigment), the direction of the patch's x axis,
 * a pigmentation image. A null or false leaves the scene's own.
 *
 * @param species      the snake's species; the scene's shape must be a snake
 * @param smoothSkin   true: no scales; the scene's shape must be a snake
 * @param tangent      the world direction of the patch's x axis, projected onto each surface point, as {x, y, z}
 * @param pigmentation an sRGB image of pigment colours over the shape's texcoords, switched on
 */
public record SkinOverrides(SnakeSpecies species, boolean smoothSkin, double[] tangent, Path pigmentation) {
    public SkinOverrides {
        if (tangent != null && tangent.length != 3) {
            throw new IllegalArgumentException("a tangent has 3 components, got " + tangent.length);
        }
    }

    /** Whether it dresses the scene's snake (a species or a smooth skin), which only a snake takes. */
    public boolean dressesSnake() {
        return species != null || smoothSkin;
    }

    /** The scene with these values in place of its own. */
    public Scene applyTo(Scene s) {
        Scene.ShapeSpec shape = s.shape();
        if (dressesSnake() && shape.kind() != Scene.ShapeKind.SNAKE) {
            throw new IllegalArgumentException("a species or a smooth skin dresses a snake, not a "
                    + shape.kind().sceneName());
        }
        StageSpec.ScalesSpec scales = shape.scales();
        if (smoothSkin) {
            scales = null;
        } else if (species != null) {
            scales = scales == null ? StageSpec.ScalesSpec.of(species)
                    : new StageSpec.ScalesSpec(species, species.scales(), scales.mapWidthPx(), scales.mapHeightPx());
        }
        TangentSource tangents = tangent == null ? shape.tangents()
                : TangentSource.projected(tangent[0], tangent[1], tangent[2]);
        Scene.ShapeSpec dressed = new Scene.ShapeSpec(shape.kind(), shape.file(), tangents, shape.ridges(),
                shape.transform(), shape.pose(), scales, shape.normalMap());

        Scene.MaterialSpec m = s.material();
        Scene.PigmentationSpec pigment = m.pigmentation();
        boolean on = m.pigmentationOn();
        if (pigmentation != null) {
            pigment = Scene.PigmentationSpec.imageFile(pigmentation);
            on = true;
        } else if (pigment.species() != null && smoothSkin) {
            pigment = Scene.PigmentationSpec.proceduralPattern();
        } else if (pigment.species() != null && species != null) {
            pigment = Scene.PigmentationSpec.ofSpecies(species);
        }
        Scene.MaterialSpec material = new Scene.MaterialSpec(m.patch(), m.settings(), m.orderTolerance(), pigment, on,
                m.diffuseWeight(), m.exposure());
        return new Scene(s.source(), s.image(), s.camera(), s.light(), dressed, material, s.mode(), s.stage());
    }
}
