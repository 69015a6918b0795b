package diffract.geometry;

/**
 * Normals and tangent fields computed from a triangle list: shared by the snake, the primitives and the OBJ
 * reader so that all meshes get their frames the same way.
 */
final class SurfaceFrames {
    /** Below this length a projected direction is taken as undefined (it was parallel to the normal). */
    private static final double DEGENERATE = 1e-6;

    private SurfaceFrames() {
    }

    /**
     * Smooth vertex normals: the area-weighted sum of the normals of the triangles around each vertex, summed over
     * all vertices at the same position (so seams do not show). Faces wound counter-clockwise give outward normals.
     * A vertex of only degenerate triangles gets +z.
     */
    static Vec3[] smoothNormals(float[] positions, int[] triangles) {
        int[] welded = Mesh.weldedVertexIds(positions);
        int vertexCount = positions.length / 3;
        Vec3[] sums = new Vec3[vertexCount];
        java.util.Arrays.fill(sums, Vec3.ZERO);
        for (int t = 0; t < triangles.length; t += 3) {
            Vec3 a = Vec3.at(positions, triangles[t]);
            Vec3 b = Vec3.at(positions, triangles[t + 1]);
            Vec3 c = Vec3.at(positions, triangles[t + 2]);
            // |cross| is twice the area: area weighting comes for free
            Vec3 faceNormal = b.minus(a).cross(c.minus(a));
            for (int k = 0; k < 3; k++) {
                int id = welded[triangles[t + k]];
                sums[id] = sums[id].plus(faceNormal);
            }
        }
        Vec3[] normals = new Vec3[vertexCount];
        for (int v = 0; v < vertexCount; v++) {
            Vec3 sum = sums[welded[v]];
            normals[v] = sum.length() > 0 ? sum.normalized() : new Vec3(0, 0, 1);
        }
        return normals;
    }

    /** Per-vertex dP/du accumulated over the triangles around each vertex (the usual tangent-from-UV construction). */
    static Vec3[] uvTangentDirections(float[] positions, float[] uvs, int[] triangles) {
        int vertexCount = positions.length / 3;
        Vec3[] sums = new Vec3[vertexCount];
        java.util.Arrays.fill(sums, Vec3.ZERO);
        for (int t = 0; t < triangles.length; t += 3) {
            int i0 = triangles[t];
            int i1 = triangles[t + 1];
            int i2 = triangles[t + 2];
            Vec3 e1 = Vec3.at(positions, i1).minus(Vec3.at(positions, i0));
            Vec3 e2 = Vec3.at(positions, i2).minus(Vec3.at(positions, i0));
            double du1 = uvs[2 * i1] - uvs[2 * i0];
            double dv1 = uvs[2 * i1 + 1] - uvs[2 * i0 + 1];
            double du2 = uvs[2 * i2] - uvs[2 * i0];
            double dv2 = uvs[2 * i2 + 1] - uvs[2 * i0 + 1];
            double det = du1 * dv2 - du2 * dv1;
            if (Math.abs(det) < 1e-20) {
                continue; // the triangle's UVs are degenerate: it says nothing about the u direction
            }
            // solve e1 = du1 T + dv1 B, e2 = du2 T + dv2 B for T = dP/du; sign(det) keeps mirrored UVs consistent
            Vec3 dPdu = e1.times(dv2).minus(e2.times(dv1)).times(1.0 / det);
            // weight by the triangle's area in 3-D, not by its (arbitrary) UV area
            double area = e1.cross(e2).length();
            for (int index : new int[] {i0, i1, i2}) {
                sums[index] = sums[index].plus(dPdu.normalized().times(area));
            }
        }
        return sums;
    }

    /** Normals as floats; each is renormalised in double first so |n| = 1 to float precision. */
    static float[] toFloats(Vec3[] vectors) {
        float[] out = new float[3 * vectors.length];
        for (int v = 0; v < vectors.length; v++) {
            vectors[v].normalized().store(out, v);
        }
        return out;
    }

    /**
     * Unit tangents orthogonal to the (already float) normals: each direction is projected onto the tangent plane
     * of its vertex and normalised; where it is undefined (zero, or parallel to the normal) some perpendicular
     * is used instead, so every vertex has a valid frame.
     */
    static float[] tangentsFrom(float[] normals, Vec3[] directions) {
        int vertexCount = normals.length / 3;
        float[] out = new float[3 * vertexCount];
        for (int v = 0; v < vertexCount; v++) {
            Vec3 n = Vec3.at(normals, v).normalized();
            Vec3 t = directions[v].projectedOff(n);
            if (t.length() < DEGENERATE * Math.max(1.0, directions[v].length())) {
                t = Vec3.anyPerpendicular(n);
            }
            t.normalized().store(out, v);
        }
        return out;
    }

    /** The same direction at every vertex. */
    static Vec3[] constant(Vec3 direction, int vertexCount) {
        Vec3[] out = new Vec3[vertexCount];
        java.util.Arrays.fill(out, direction);
        return out;
    }
}
