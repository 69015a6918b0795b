package diffract.geometry;

import java.util.HashMap;
import java.util.Map;

/**
 * An indexed triangle mesh with everything the diffraction shaders need per vertex: position, unit normal, unit
 * tangent orthogonal to the normal (the direction of the nanostructure patch's x axis, i.e. its columns), and
 * optionally texture coordinates. Triangles are counter-clockwise seen from outside (the side the normal points
 * to). Immutable: arrays are copied in and out.
 *
 * <p>Vertices that share a position but differ in another attribute (a texture seam, the poles of a tube) are
 * separate vertices; {@link #isClosed()} therefore welds vertices by exact position before counting edges.
 */
public final class Mesh {
    /** How far |n|, |t| may be from 1 and t.n from 0: float rounding of unit vectors stays far below this. */
    static final double UNIT_TOLERANCE = 1e-4;

    private final float[] positions;
    private final float[] normals;
    private final float[] tangents;
    private final float[] uvs;
    private final int[] triangles;

    private Mesh(float[] positions, float[] normals, float[] tangents, float[] uvs, int[] triangles) {
        this.positions = positions;
        this.normals = normals;
        this.tangents = tangents;
        this.uvs = uvs;
        this.triangles = triangles;
    }

    /**
     * @param positions xyz per vertex
     * @param normals   unit xyz per vertex
     * @param tangents  unit xyz per vertex, orthogonal to the normal
     * @param uvs       uv per vertex, or null for a mesh without texture coordinates
     * @param triangles three vertex indices per triangle
     * @throws IllegalArgumentException when sizes disagree, an index is out of range, a value is not finite, or a
     *                                  normal/tangent is not unit or the two are not orthogonal
     */
    public static Mesh of(float[] positions, float[] normals, float[] tangents, float[] uvs, int[] triangles) {
        if (positions.length == 0 || positions.length % 3 != 0) {
            throw new IllegalArgumentException("positions must be a positive multiple of 3 floats, got "
                    + positions.length);
        }
        int vertexCount = positions.length / 3;
        requireLength("normals", normals, 3 * vertexCount);
        requireLength("tangents", tangents, 3 * vertexCount);
        if (uvs != null) {
            requireLength("uvs", uvs, 2 * vertexCount);
        }
        if (triangles.length == 0 || triangles.length % 3 != 0) {
            throw new IllegalArgumentException("triangle indices must be a positive multiple of 3, got "
                    + triangles.length);
        }
        for (int i = 0; i < triangles.length; i++) {
            if (triangles[i] < 0 || triangles[i] >= vertexCount) {
                throw new IllegalArgumentException("triangle " + i / 3 + " uses vertex " + triangles[i]
                        + ", outside [0, " + vertexCount + ")");
            }
        }
        requireFinite("positions", positions);
        requireFinite("uvs", uvs);
        for (int v = 0; v < vertexCount; v++) {
            Vec3 n = Vec3.at(normals, v);
            Vec3 t = Vec3.at(tangents, v);
            if (Math.abs(n.length() - 1) > UNIT_TOLERANCE || Math.abs(t.length() - 1) > UNIT_TOLERANCE) {
                throw new IllegalArgumentException("vertex " + v + ": normal " + n + " and tangent " + t
                        + " must be unit vectors");
            }
            if (Math.abs(n.dot(t)) > UNIT_TOLERANCE) {
                throw new IllegalArgumentException("vertex " + v + ": tangent " + t + " is not orthogonal to normal "
                        + n + " (t.n = " + n.dot(t) + ")");
            }
        }
        return new Mesh(positions.clone(), normals.clone(), tangents.clone(), uvs == null ? null : uvs.clone(),
                triangles.clone());
    }

    private static void requireLength(String what, float[] values, int expected) {
        if (values == null || values.length != expected) {
            throw new IllegalArgumentException(what + ": expected " + expected + " floats, got "
                    + (values == null ? "none" : values.length));
        }
    }

    private static void requireFinite(String what, float[] values) {
        if (values == null) {
            return;
        }
        for (int i = 0; i < values.length; i++) {
            if (!Float.isFinite(values[i])) {
                throw new IllegalArgumentException(what + "[" + i + "] is " + values[i]);
            }
        }
    }

    public int vertexCount() {
        return positions.length / 3;
    }

    public int triangleCount() {
        return triangles.length / 3;
    }

    /** A copy of the positions, xyz per vertex. */
    public float[] positions() {
        return positions.clone();
    }

    /** A copy of the unit normals, xyz per vertex. */
    public float[] normals() {
        return normals.clone();
    }

    /** A copy of the unit tangents (the patch's x axis on the surface), xyz per vertex. */
    public float[] tangents() {
        return tangents.clone();
    }

    public boolean hasUvs() {
        return uvs != null;
    }

    /** A copy of the texture coordinates, uv per vertex; throws if the mesh has none. */
    public float[] uvs() {
        if (uvs == null) {
            throw new IllegalStateException("the mesh has no texture coordinates");
        }
        return uvs.clone();
    }

    /** A copy of the triangle indices, three per triangle. */
    public int[] triangles() {
        return triangles.clone();
    }

    /** Axis-aligned bounds: {minX, minY, minZ, maxX, maxY, maxZ}. */
    public double[] bounds() {
        double[] b = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE,
            -Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (int i = 0; i < positions.length; i++) {
            b[i % 3] = Math.min(b[i % 3], positions[i]);
            b[3 + i % 3] = Math.max(b[3 + i % 3], positions[i]);
        }
        return b;
    }

    /**
     * Edges (between welded vertices) that are not shared by exactly two triangles: boundary edges and
     * non-manifold edges. Zero for a watertight surface.
     */
    public int unpairedEdgeCount() {
        int[] welded = weldedVertexIds(positions);
        Map<Long, Integer> uses = new HashMap<>();
        for (int t = 0; t < triangles.length; t += 3) {
            for (int k = 0; k < 3; k++) {
                int a = welded[triangles[t + k]];
                int b = welded[triangles[t + (k + 1) % 3]];
                long key = ((long) Math.min(a, b) << 32) | Math.max(a, b);
                uses.merge(key, 1, Integer::sum);
            }
        }
        int unpaired = 0;
        for (int count : uses.values()) {
            if (count != 2) {
                unpaired++;
            }
        }
        return unpaired;
    }

    /** True when every edge is shared by exactly two triangles (after welding equal positions). */
    public boolean isClosed() {
        return unpairedEdgeCount() == 0;
    }

    /** For each vertex, the index of the first vertex with exactly the same position. */
    static int[] weldedVertexIds(float[] positions) {
        int vertexCount = positions.length / 3;
        int[] ids = new int[vertexCount];
        Map<PositionKey, Integer> first = new HashMap<>();
        for (int v = 0; v < vertexCount; v++) {
            PositionKey key = new PositionKey(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
            Integer existing = first.putIfAbsent(key, v);
            ids[v] = existing == null ? v : existing;
        }
        return ids;
    }

    /** Exact float equality, with -0 and +0 the same position. */
    private record PositionKey(float x, float y, float z) {
        PositionKey {
            x += 0.0f;
            y += 0.0f;
            z += 0.0f;
        }
    }
}
