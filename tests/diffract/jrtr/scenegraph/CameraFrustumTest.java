package diffract.jrtr.scenegraph;

import org.junit.jupiter.api.Test;

import javax.vecmath.Matrix4f;
import javax.vecmath.Point3f;
import javax.vecmath.Point4f;
import javax.vecmath.Vector3f;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Camera and frustum matrices against values computed by hand. */
class CameraFrustumTest {
    private static final float EPS = 1e-6f;

    private static void assertMatrix(float[] expectedRowMajor, Matrix4f actual) {
        for (int r = 0; r < 4; r++) {
            for (int c = 0; c < 4; c++) {
                assertEquals(expectedRowMajor[r * 4 + c], actual.getElement(r, c), EPS, "element " + r + "," + c
                        + " of\n" + actual);
            }
        }
    }

    @Test
    void eyeOnThePositiveZAxisGivesATranslationByMinusFive() {
        Camera camera = new Camera(new Point3f(0, 0, 5), new Point3f(0, 0, 0), new Vector3f(0, 1, 0));
        assertMatrix(new float[] {
            1, 0, 0, 0,
            0, 1, 0, 0,
            0, 0, 1, -5,
            0, 0, 0, 1}, camera.viewMatrix());
        assertMatrix(new float[] {
            1, 0, 0, 0,
            0, 1, 0, 0,
            0, 0, 1, 5,
            0, 0, 0, 1}, camera.cameraMatrix());
    }

    @Test
    void cameraOnTheXAxisLookingAtTheOrigin() {
        // w = (1,0,0), u = up x w = (0,1,0) x (1,0,0) = (0,0,-1), v = w x u = (0,1,0)
        Camera camera = new Camera(new Point3f(3, 0, 0), new Point3f(0, 0, 0), new Vector3f(0, 2, 0));
        // C = [u v w eye]: columns (0,0,-1), (0,1,0), (1,0,0), (3,0,0)
        assertMatrix(new float[] {
            0, 0, 1, 3,
            0, 1, 0, 0,
            -1, 0, 0, 0,
            0, 0, 0, 1}, camera.cameraMatrix());
        // view = C^-1: rows u, v, w and translation -(u.e, v.e, w.e) = (0, 0, -3)
        assertMatrix(new float[] {
            0, 0, -1, 0,
            0, 1, 0, 0,
            1, 0, 0, -3,
            0, 0, 0, 1}, camera.viewMatrix());
        // the look-at point is straight ahead, 3 units down -z
        Point3f origin = new Point3f(0, 0, 0);
        camera.viewMatrix().transform(origin);
        assertEquals(0, origin.x, EPS);
        assertEquals(0, origin.y, EPS);
        assertEquals(-3, origin.z, EPS);
    }

    @Test
    void viewMatrixIsTheInverseOfTheCameraMatrix() {
        Camera camera = new Camera(new Point3f(1, 2, 6), new Point3f(0.5f, 0, -1), new Vector3f(0.1f, 1, 0));
        Matrix4f product = new Matrix4f();
        product.mul(camera.cameraMatrix(), camera.viewMatrix());
        Matrix4f identity = new Matrix4f();
        identity.setIdentity();
        assertTrue(identity.epsilonEquals(product, 1e-5f), "C * C^-1 =\n" + product);
    }

    @Test
    void degenerateCamerasAreRejected() {
        assertThrows(IllegalArgumentException.class,
                () -> new Camera(new Point3f(1, 1, 1), new Point3f(1, 1, 1), new Vector3f(0, 1, 0)));
        assertThrows(IllegalArgumentException.class,
                () -> new Camera(new Point3f(0, 5, 0), new Point3f(0, 0, 0), new Vector3f(0, 1, 0)));
    }

    @Test
    void ninetyDegreeFrustumMatchesTheHandComputedMatrix() {
        // t = tan(45 deg) = 1, aspect 2, near 1, far 3: (n+f)/(n-f) = -2, 2nf/(n-f) = -3
        Frustum frustum = new Frustum(1, 3, 2, 90);
        assertMatrix(new float[] {
            0.5f, 0, 0, 0,
            0, 1, 0, 0,
            0, 0, -2, -3,
            0, 0, -1, 0}, frustum.projectionMatrix());
    }

    @Test
    void nearAndFarPlanesMapToMinusOneAndOne() {
        Frustum frustum = new Frustum(0.5f, 20f, 1.5f, 60);
        assertEquals(-1, ndcDepth(frustum, -0.5f), 1e-5);
        assertEquals(1, ndcDepth(frustum, -20f), 1e-5);
        // the top edge of the field of view maps to y = 1
        Point4f top = new Point4f(0, (float) Math.tan(Math.toRadians(30)) * 4, -4, 1);
        frustum.projectionMatrix().transform(top);
        assertEquals(1, top.y / top.w, 1e-5);
    }

    private static float ndcDepth(Frustum frustum, float z) {
        Point4f p = new Point4f(0, 0, z, 1);
        frustum.projectionMatrix().transform(p);
        return p.z / p.w;
    }

    @Test
    void invalidFrustaAreRejected() {
        assertThrows(IllegalArgumentException.class, () -> new Frustum(0, 10, 1, 60));
        assertThrows(IllegalArgumentException.class, () -> new Frustum(2, 1, 1, 60));
        assertThrows(IllegalArgumentException.class, () -> new Frustum(1, 10, 1, 180));
        assertThrows(IllegalArgumentException.class, () -> new Frustum(1, 10, 0, 60));
    }
}
