package diffract.jrtr.scenegraph;

/** Small meshes for tests, debugging and simple scenes. All have positions, normals, tangents and texcoords. */
public final class Shapes {
    private Shapes() {
    }

    /**
     * Axis-aligned rectangle in the plane z = {@code z}, from (x0, y0) to (x1, y1), facing +z (counter-clockwise
     * seen from +z), tangent +x, texcoords (0,0) at (x0, y0) to (1,1) at (x1, y1).
     */
    public static Shape rectangle(String name, float x0, float y0, float x1, float y1, float z) {
        VertexData data = VertexData.builder(4)
                .positions(x0, y0, z, x1, y0, z, x1, y1, z, x0, y1, z)
                .normals(0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1)
                .tangents(1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0)
                .texcoords(0, 0, 1, 0, 1, 1, 0, 1)
                .indices(0, 1, 2, 0, 2, 3)
                .build();
        return new Shape(name, data);
    }

    /** The square [-1, 1]^2 at z = 0: with identity matrices it fills the whole viewport. */
    public static Shape fullScreenQuad() {
        return rectangle("full-screen quad", -1, -1, 1, 1, 0);
    }

    /** One triangle with the given corners (counter-clockwise = front), flat normal. */
    public static Shape triangle(String name, float[] a, float[] b, float[] c) {
        float[] e1 = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        float[] e2 = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        float[] n = normalize(new float[] {
            e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]});
        float[] t = normalize(e1);
        VertexData data = VertexData.builder(3)
                .positions(a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2])
                .normals(n[0], n[1], n[2], n[0], n[1], n[2], n[0], n[1], n[2])
                .tangents(t[0], t[1], t[2], t[0], t[1], t[2], t[0], t[1], t[2])
                .texcoords(0, 0, 1, 0, 0, 1)
                .indices(0, 1, 2)
                .build();
        return new Shape(name, data);
    }

    /** Cube [-h, h]^3 with h = {@code halfSize}: 24 vertices so each face has its own flat normal. */
    public static Shape cube(float halfSize) {
        // per face: normal, tangent; the bitangent is normal x tangent
        float[][] faces = {
            {1, 0, 0, 0, 0, -1}, {-1, 0, 0, 0, 0, 1},
            {0, 1, 0, 1, 0, 0}, {0, -1, 0, 1, 0, 0},
            {0, 0, 1, 1, 0, 0}, {0, 0, -1, -1, 0, 0},
        };
        float[] positions = new float[24 * 3];
        float[] normals = new float[24 * 3];
        float[] tangents = new float[24 * 3];
        float[] texcoords = new float[24 * 2];
        int[] indices = new int[36];
        float[][] corners = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (int f = 0; f < 6; f++) {
            float[] n = {faces[f][0], faces[f][1], faces[f][2]};
            float[] t = {faces[f][3], faces[f][4], faces[f][5]};
            float[] b = {n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0]};
            for (int c = 0; c < 4; c++) {
                int v = f * 4 + c;
                for (int k = 0; k < 3; k++) {
                    positions[v * 3 + k] = halfSize * (n[k] + corners[c][0] * t[k] + corners[c][1] * b[k]);
                    normals[v * 3 + k] = n[k];
                    tangents[v * 3 + k] = t[k];
                }
                texcoords[v * 2] = (corners[c][0] + 1) / 2;
                texcoords[v * 2 + 1] = (corners[c][1] + 1) / 2;
            }
            int[] quad = {0, 1, 2, 0, 2, 3};
            for (int i = 0; i < 6; i++) {
                indices[f * 6 + i] = f * 4 + quad[i];
            }
        }
        VertexData data = VertexData.builder(24)
                .positions(positions).normals(normals).tangents(tangents).texcoords(texcoords)
                .indices(indices).build();
        return new Shape("cube", data);
    }

    private static float[] normalize(float[] v) {
        float length = (float) Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (length == 0) {
            throw new IllegalArgumentException("degenerate triangle");
        }
        return new float[] {v[0] / length, v[1] / length, v[2] / length};
    }
}
