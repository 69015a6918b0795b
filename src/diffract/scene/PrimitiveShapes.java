package diffract.scene;

import diffract.geometry.Mesh;
import diffract.geometry.SnakeMesh;
import diffract.jrtr.scenegraph.Shape;
import diffract.jrtr.scenegraph.VertexData;


/**
 * The shapes a scene can name besides an OBJ file: a sphere, a plane, an open cylinder and the procedural snake,
 * all about the origin within the unit cube, with positions, normals, texcoords and tangents. The tangent carries the
 * patch's x axis (its columns) over the surface: it is the world direction {@code tangentAlong} projected onto
 * each vertex's tangent plane, so e.g. (1, 0, 0) lays the patch's x axis horizontally everywhere it can. Where the
 * direction is (nearly) normal to the surface the projection vanishes and the shape's own fallback direction is
 * used (around the y axis for sphere and cylinder).
 */
public final class PrimitiveShapes {
    /** Below this length a projected tangent is too short to normalise reliably. */
    private static final double DEGENERATE_TANGENT = 1e-3;

    private PrimitiveShapes() {
    }

    /** The unit sphere, poles on the y axis, 48 stacks x 96 slices; texcoord u around, v from pole to pole. */
    public static Shape sphere(double[] tangentAlong) {
        int stacks = 48;
        int slices = 96;
        MeshBuilder mesh = new MeshBuilder((stacks + 1) * (slices + 1));
        for (int i = 0; i <= stacks; i++) {
            double theta = Math.PI * i / stacks;
            for (int j = 0; j <= slices; j++) {
                double phi = 2 * Math.PI * j / slices;
                double[] n = {Math.sin(theta) * Math.sin(phi), Math.cos(theta), Math.sin(theta) * Math.cos(phi)};
                double[] around = {Math.cos(phi), 0, -Math.sin(phi)};
                mesh.vertex(n, n, tangent(tangentAlong, n, around), (double) j / slices, 1.0 - (double) i / stacks);
            }
        }
        mesh.grid(stacks, slices);
        return mesh.build("sphere");
    }

    /** The square [-1, 1]^2 in the plane z = 0, facing +z, subdivided 8 x 8. */
    public static Shape plane(double[] tangentAlong) {
        int cells = 8;
        MeshBuilder mesh = new MeshBuilder((cells + 1) * (cells + 1));
        double[] n = {0, 0, 1};
        double[] t = tangent(tangentAlong, n, new double[] {1, 0, 0});
        for (int i = 0; i <= cells; i++) {
            double y = 1.0 - 2.0 * i / cells;
            for (int j = 0; j <= cells; j++) {
                double x = -1.0 + 2.0 * j / cells;
                mesh.vertex(new double[] {x, y, 0}, n, t, (double) j / cells, 1.0 - (double) i / cells);
            }
        }
        mesh.grid(cells, cells);
        return mesh.build("plane");
    }

    /** An open cylinder of radius 0.6 around the y axis, y in [-1, 1], 96 slices. */
    public static Shape cylinder(double[] tangentAlong) {
        int rings = 8;
        int slices = 96;
        double radius = 0.6;
        MeshBuilder mesh = new MeshBuilder((rings + 1) * (slices + 1));
        for (int i = 0; i <= rings; i++) {
            double y = 1.0 - 2.0 * i / rings;
            for (int j = 0; j <= slices; j++) {
                double phi = 2 * Math.PI * j / slices;
                double[] n = {Math.sin(phi), 0, Math.cos(phi)};
                double[] around = {Math.cos(phi), 0, -Math.sin(phi)};
                mesh.vertex(new double[] {radius * n[0], y, radius * n[2]}, n, tangent(tangentAlong, n, around),
                        (double) j / slices, 1.0 - (double) i / rings);
            }
        }
        mesh.grid(rings, slices);
        return mesh.build("cylinder");
    }

    /**
     * The procedural snake ({@link SnakeMesh}), scaled so its length spans [-1, 1] and centred on the origin like the
     * other shapes. Its tangents are its own orientation field (the ridges along the body by default), not a
     * projected world direction.
     */
    public static Shape snake(SnakeMesh.Parameters parameters) {
        Mesh mesh = SnakeMesh.generate(parameters).mesh();
        double[] bounds = mesh.bounds(); // min x, y, z, max x, y, z
        double scale = 2.0 / Math.max(1e-12, bounds[3] - bounds[0]);
        float[] p = mesh.positions();
        float[] positions = new float[p.length];
        for (int i = 0; i < p.length; i += 3) {
            for (int k = 0; k < 3; k++) {
                positions[i + k] = (float) ((p[i + k] - 0.5 * (bounds[k] + bounds[k + 3])) * scale);
            }
        }
        return new Shape("snake", VertexData.builder(mesh.vertexCount()).positions(positions).normals(mesh.normals())
                .tangents(mesh.tangents()).texcoords(mesh.uvs()).indices(mesh.triangles()).build());
    }

    /** {@code along} minus its normal component, normalised; {@code fallback} where that vanishes. */
    static double[] tangent(double[] along, double[] normal, double[] fallback) {
        double[] t = project(along, normal);
        return length(t) > DEGENERATE_TANGENT * Math.max(1e-12, length(along)) ? normalize(t)
                : normalize(project(fallback, normal));
    }

    private static double[] project(double[] v, double[] n) {
        double d = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
        return new double[] {v[0] - d * n[0], v[1] - d * n[1], v[2] - d * n[2]};
    }

    private static double length(double[] v) {
        return Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }

    private static double[] normalize(double[] v) {
        double l = length(v);
        return new double[] {v[0] / l, v[1] / l, v[2] / l};
    }

    /** Collects vertices row by row and triangulates a (rows + 1) x (cols + 1) vertex grid counter-clockwise. */
    private static final class MeshBuilder {
        private final float[] positions;
        private final float[] normals;
        private final float[] tangents;
        private final float[] texcoords;
        private int[] indices;
        private int count;

        MeshBuilder(int vertices) {
            positions = new float[3 * vertices];
            normals = new float[3 * vertices];
            tangents = new float[3 * vertices];
            texcoords = new float[2 * vertices];
        }

        void vertex(double[] p, double[] n, double[] t, double u, double v) {
            for (int k = 0; k < 3; k++) {
                positions[3 * count + k] = (float) p[k];
                normals[3 * count + k] = (float) n[k];
                tangents[3 * count + k] = (float) t[k];
            }
            texcoords[2 * count] = (float) u;
            texcoords[2 * count + 1] = (float) v;
            count++;
        }

        /**
         * Rows run from the top (+y) down and columns to the right as seen from outside, so (a, c, b) and
         * (b, c, d) are counter-clockwise seen from outside (front faces, should culling ever be switched on).
         */
        void grid(int rows, int cols) {
            indices = new int[rows * cols * 6];
            int k = 0;
            for (int i = 0; i < rows; i++) {
                for (int j = 0; j < cols; j++) {
                    int a = i * (cols + 1) + j;
                    int b = a + 1;
                    int c = a + cols + 1;
                    int d = c + 1;
                    indices[k++] = a;
                    indices[k++] = c;
                    indices[k++] = b;
                    indices[k++] = b;
                    indices[k++] = c;
                    indices[k++] = d;
                }
            }
        }

        Shape build(String name) {
            return new Shape(name, VertexData.builder(count).positions(positions).normals(normals)
                    .tangents(tangents).texcoords(texcoords).indices(indices).build());
        }
    }
}
