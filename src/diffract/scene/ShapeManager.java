package diffract.scene;

import diffract.geometry.Mesh;
import diffract.geometry.ObjReader;
import diffract.geometry.SnakeMesh;
import diffract.geometry.TangentSource;
import diffract.jrtr.scenegraph.Shape;
import diffract.jrtr.scenegraph.VertexAttribute;
import diffract.jrtr.scenegraph.VertexData;

/**
 * The shape's constants manager: builds the mesh a scene names (the procedural snake, an OBJ file or a primitive
 * of {@link PrimitiveShapes}) with positions, normals, tangents and texcoords, then applies the scene's transform:
 * p' = R (s p) + t with R = Rz Ry Rx (degrees about x first), normals and tangents turned by R (a uniform scale
 * leaves directions alone).
 */
final class ShapeManager {
    private ShapeManager() {
    }

    static Shape shape(Scene.ShapeSpec spec) {
        Shape shape = untransformed(spec);
        return transformed(shape, spec.transform());
    }

    private static Shape untransformed(Scene.ShapeSpec spec) {
        switch (spec.kind()) {
            case SNAKE:
                return PrimitiveShapes.snake(snakeParameters(spec));
            case OBJ:
                return fromMesh(spec.file().getFileName().toString(), ObjReader.read(spec.file(), spec.tangents()));
            case PLANE:
                return PrimitiveShapes.plane(direction(spec.tangents()));
            case CYLINDER:
                return PrimitiveShapes.cylinder(direction(spec.tangents()));
            default:
                return PrimitiveShapes.sphere(direction(spec.tangents()));
        }
    }

    /** The procedural snake of a shape of kind snake: default size, the scene's ridges and pose. */
    static SnakeMesh.Parameters snakeParameters(Scene.ShapeSpec spec) {
        return SnakeMesh.Parameters.defaults().withRidges(spec.ridges()).withPose(spec.pose());
    }

    private static double[] direction(TangentSource tangents) {
        TangentSource.Projected projected = (TangentSource.Projected) tangents;
        return new double[] {projected.x(), projected.y(), projected.z()};
    }

    /** An OBJ without texture coordinates gets u = v = 0 everywhere: the shader needs the attribute. */
    static Shape fromMesh(String name, Mesh mesh) {
        float[] uvs = mesh.hasUvs() ? mesh.uvs() : new float[2 * mesh.vertexCount()];
        return new Shape(name, VertexData.builder(mesh.vertexCount()).positions(mesh.positions())
                .normals(mesh.normals()).tangents(mesh.tangents()).texcoords(uvs).indices(mesh.triangles()).build());
    }

    static Shape transformed(Shape shape, Scene.Transform transform) {
        double[] r = transform.rotateDeg();
        double[] t = transform.translate();
        if (r[0] == 0 && r[1] == 0 && r[2] == 0 && t[0] == 0 && t[1] == 0 && t[2] == 0 && transform.scale() == 1) {
            return shape;
        }
        double[][] rotation = rotation(r);
        VertexData data = shape.vertexData();
        float[] positions = data.attribute(VertexAttribute.POSITION).clone();
        float[] normals = data.attribute(VertexAttribute.NORMAL).clone();
        float[] tangents = data.attribute(VertexAttribute.TANGENT).clone();
        for (int i = 0; i < positions.length; i += 3) {
            turn(rotation, positions, i, transform.scale(), t);
            turn(rotation, normals, i, 1, new double[3]);
            turn(rotation, tangents, i, 1, new double[3]);
        }
        return new Shape(shape.name(), VertexData.builder(data.vertexCount()).positions(positions).normals(normals)
                .tangents(tangents).texcoords(data.attribute(VertexAttribute.TEXCOORD)).indices(data.indices()).build());
    }

    private static void turn(double[][] rotation, float[] xyz, int i, double scale, double[] translate) {
        double x = xyz[i] * scale;
        double y = xyz[i + 1] * scale;
        double z = xyz[i + 2] * scale;
        for (int k = 0; k < 3; k++) {
            xyz[i + k] = (float) (rotation[k][0] * x + rotation[k][1] * y + rotation[k][2] * z + translate[k]);
        }
    }

    /** Rz Ry Rx for angles in degrees. */
    static double[][] rotation(double[] deg) {
        double[][] rx = axis(0, Math.toRadians(deg[0]));
        double[][] ry = axis(1, Math.toRadians(deg[1]));
        double[][] rz = axis(2, Math.toRadians(deg[2]));
        return multiply(rz, multiply(ry, rx));
    }

    private static double[][] axis(int axis, double angle) {
        double c = Math.cos(angle);
        double s = Math.sin(angle);
        int a = (axis + 1) % 3;
        int b = (axis + 2) % 3;
        double[][] m = new double[3][3];
        m[axis][axis] = 1;
        m[a][a] = c;
        m[a][b] = -s;
        m[b][a] = s;
        m[b][b] = c;
        return m;
    }

    private static double[][] multiply(double[][] p, double[][] q) {
        double[][] m = new double[3][3];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                for (int k = 0; k < 3; k++) {
                    m[i][j] += p[i][k] * q[k][j];
                }
            }
        }
        return m;
    }
}
