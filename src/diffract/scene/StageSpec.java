package diffract.scene;

import diffract.colour.ToneMapping;
import diffract.geometry.ScaleLattice;
import diffract.geometry.SnakeSpecies;

import java.nio.file.Path;

/**
 * The scene's staging keys, parsed ({@link StageKeys}; schema in {@code docs/guide/scene-format.md}): environment light,
 * ground and shadow, tone mapping. Absent keys stage nothing.
 *
 * @param environment the environment, or null
 * @param ground      the ground, or null
 * @param toneMapping the display's tone mapping ({@link ToneMapping#clip()} when the key is absent)
 */
public record StageSpec(EnvironmentSpec environment, GroundSpec ground, ToneMapping toneMapping) {
    public static StageSpec none() {
        return new StageSpec(null, null, ToneMapping.clip());
    }

    /**
     * @param file               a Radiance .hdr environment, or null for the procedural clear sky
     * @param scale              multiplies the file's radiance (key-light units)
     * @param rotateDeg          turns the map about the world y axis, degrees
     * @param skyIrradianceRatio the clear sky's horizontal irradiance over the key light's normal irradiance
     * @param lights             extended lights the median cut makes (a power of two)
     */
    public record EnvironmentSpec(Path file, double scale, double rotateDeg, double skyIrradianceRatio, int lights) {
    }

    /**
     * @param albedoSrgb the ground's colour, display sRGB in [0, 1]
     * @param mottle     relative amplitude of its noise
     * @param shadows    whether the key light casts shadows
     */
    public record GroundSpec(double[] albedoSrgb, double mottle, boolean shadows) {
    }

    /**
     * A snake's scales: the species (its defaults), the lattice with the scene's overrides, the frame map's size.
     */
    public record ScalesSpec(SnakeSpecies species, ScaleLattice.Parameters lattice, int mapWidthPx, int mapHeightPx) {
        /** The frame map's default size: across the body, along it (a snake is long). */
        public static final int DEFAULT_MAP_WIDTH_PX = 512;
        public static final int DEFAULT_MAP_HEIGHT_PX = 4096;

        /** The species' own scales on a frame map of the default size. */
        public static ScalesSpec of(SnakeSpecies species) {
            return new ScalesSpec(species, species.scales(), DEFAULT_MAP_WIDTH_PX, DEFAULT_MAP_HEIGHT_PX);
        }
    }

    /** An OBJ shape's tangent-space normal map (OpenGL convention), or none. */
    public record NormalMapSpec(Path file) {
    }
}
