package diffract.geometry;

/**
 * Where a mesh's per-vertex tangents (the direction of the nanostructure patch's x axis on the surface) come from.
 * Every source ends the same way: the direction is projected onto the vertex's tangent plane and normalised.
 */
public sealed interface TangentSource {
    /** Explicit per-vertex {@code tg x y z} lines in the OBJ file, one per {@code v} line, in the same order. */
    record Explicit() implements TangentSource {
    }

    /** dP/du from the texture coordinates: the patch's x axis follows the texture's u axis. */
    record FromUvs() implements TangentSource {
    }

    /**
     * One world direction projected onto every tangent plane, e.g. (0, 1, 0) for ridges along a vertical axis.
     * Where the direction is parallel to the normal the field is undefined and some perpendicular is used.
     */
    record Projected(double x, double y, double z) implements TangentSource {
        public Projected {
            if (!(Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z)) || x * x + y * y + z * z == 0) {
                throw new IllegalArgumentException("a tangent direction must be a finite non-zero vector");
            }
        }

        Vec3 direction() {
            return new Vec3(x, y, z).normalized();
        }
    }

    static TangentSource explicit() {
        return new Explicit();
    }

    static TangentSource fromUvs() {
        return new FromUvs();
    }

    static TangentSource projected(double x, double y, double z) {
        return new Projected(x, y, z);
    }
}
