package diffract.geometry;

import diffract.util.TestReport;
import diffract.util.UserInputException;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The procedural snake is a closed, well-framed surface of the size a scene expects. */
class SnakeMeshTest {
    static SnakeMesh snake;
    static Mesh mesh;

    @BeforeAll
    static void generate() {
        snake = SnakeMesh.generate(SnakeMesh.Parameters.defaults());
        mesh = snake.mesh();
    }

    @Test
    void triangleCountIsBetween20kAnd60k() {
        int triangles = mesh.triangleCount();
        TestReport.line(SnakeMeshTest.class, "snake: " + triangles + " triangles, " + mesh.vertexCount() + " vertices");
        assertEquals(SnakeMesh.Parameters.defaults().triangleCount(), triangles);
        assertTrue(triangles >= 20_000 && triangles <= 60_000, "triangles: " + triangles);
    }

    @Test
    void everyEdgeIsSharedByExactlyTwoTriangles() {
        assertEquals(0, mesh.unpairedEdgeCount());
        assertTrue(mesh.isClosed());
    }

    @Test
    void normalsAreUnitAndTangentsUnitAndOrthogonalToThem() {
        float[] n = mesh.normals();
        float[] t = mesh.tangents();
        double worstNormal = 0;
        double worstTangent = 0;
        double worstDot = 0;
        for (int v = 0; v < mesh.vertexCount(); v++) {
            Vec3 normal = Vec3.at(n, v);
            Vec3 tangent = Vec3.at(t, v);
            worstNormal = Math.max(worstNormal, Math.abs(normal.length() - 1));
            worstTangent = Math.max(worstTangent, Math.abs(tangent.length() - 1));
            worstDot = Math.max(worstDot, Math.abs(normal.dot(tangent)));
        }
        assertTrue(worstNormal < 1e-5, "| |n| - 1 | up to " + worstNormal);
        assertTrue(worstTangent < 1e-5, "| |t| - 1 | up to " + worstTangent);
        assertTrue(worstDot < 1e-5, "|t.n| up to " + worstDot);
    }

    @Test
    void normalsPointOutOfTheBody() {
        float[] p = mesh.positions();
        float[] n = mesh.normals();
        float[] c = snake.centreCurvePoints();
        for (int v = 0; v < mesh.vertexCount(); v++) {
            Vec3 outward = Vec3.at(p, v).minus(Vec3.at(c, v));
            assertTrue(outward.dot(Vec3.at(n, v)) > 0, "vertex " + v + " normal points inwards");
        }
    }

    @Test
    void enclosedVolumeIsPositiveSoTrianglesAreCounterClockwiseFromOutside() {
        float[] p = mesh.positions();
        int[] tri = mesh.triangles();
        double sixVolume = 0;
        for (int i = 0; i < tri.length; i += 3) {
            sixVolume += Vec3.at(p, tri[i]).dot(Vec3.at(p, tri[i + 1]).cross(Vec3.at(p, tri[i + 2])));
        }
        double volume = sixVolume / 6;
        // a 1.2 m tube of about 1.5 cm mean half-width: pi r^2 h' L ~ 7e-4 m^3
        assertTrue(volume > 2e-4 && volume < 2e-3, "volume " + volume);
    }

    @Test
    void uvsLieInTheUnitSquareAndSpanIt() {
        float[] uv = mesh.uvs();
        float minV = 1;
        float maxV = 0;
        for (int i = 0; i < uv.length; i++) {
            assertTrue(uv[i] >= 0 && uv[i] <= 1, "uv component " + uv[i]);
            if (i % 2 == 1) {
                minV = Math.min(minV, uv[i]);
                maxV = Math.max(maxV, uv[i]);
            }
        }
        assertEquals(0, minV);
        assertEquals(1, maxV);
    }

    @Test
    void tangentsRunAlongTheBodyByDefaultAndAroundItOnRequest() {
        // mid-body, top of the back: the body runs along -x (head at +x), so the tangent is near (+-1, 0, 0)
        // unless a bend turns it; "around" is orthogonal to "along" at every vertex
        Mesh around = SnakeMesh.generate(SnakeMesh.Parameters.defaults().withRidges(SnakeMesh.RidgeDirection.AROUND_BODY))
                .mesh();
        float[] along = mesh.tangents();
        float[] across = around.tangents();
        float[] p = mesh.positions();
        int checked = 0;
        for (int v = 0; v < mesh.vertexCount(); v++) {
            assertTrue(Math.abs(Vec3.at(along, v).dot(Vec3.at(across, v))) < 1e-5, "vertex " + v);
        }
        float[] c = snake.centreCurvePoints();
        for (int v = 0; v + 1 < mesh.vertexCount(); v++) {
            // along-body tangent points from this ring's centre towards the next ring's (head to tail)
            Vec3 t = Vec3.at(along, v);
            if (Math.abs(p[3 * v]) < 0.3) {
                assertTrue(t.x() < -0.5, "mid-body tangent " + t + " should point to the tail (-x)");
                checked++;
            }
        }
        assertTrue(checked > 1000);
        assertTrue(c.length == p.length);
    }

    @Test
    void isDeterministic() {
        Mesh again = SnakeMesh.generate(SnakeMesh.Parameters.defaults()).mesh();
        assertArrayEquals(mesh.positions(), again.positions());
        assertArrayEquals(mesh.tangents(), again.tangents());
    }

    @Test
    void coarseSnakesAreClosedToo() {
        Mesh coarse = SnakeMesh.generate(SnakeMesh.Parameters.defaults().withResolution(12, 8)).mesh();
        assertEquals(2 * 12 * 8, coarse.triangleCount());
        assertTrue(coarse.isClosed());
    }

    @Test
    void implausibleParametersAreRejectedWithTheirName() {
        UserInputException e = assertThrows(UserInputException.class,
                () -> SnakeMesh.Parameters.defaults().withResolution(4, 64));
        assertTrue(e.getMessage().contains("rings"), e.getMessage());
        e = assertThrows(UserInputException.class, () -> new SnakeMesh.Parameters(1, 0.5, 0.85, 0.25, 2, 0.1, 0.02,
                100, 32, SnakeMesh.RidgeDirection.ALONG_BODY, SnakeMesh.Pose.S_CURVE));
        assertTrue(e.getMessage().contains("radiusM"), e.getMessage());
    }

    @Test
    void theCoiledSnakeIsClosedLiesOnTheGroundAndItsCoilsDoNotTouch() {
        SnakeMesh coiled = SnakeMesh.generate(SnakeMesh.Parameters.defaults().withPose(SnakeMesh.Pose.COILED));
        Mesh m = coiled.mesh();
        assertTrue(m.isClosed());
        double[] b = m.bounds();
        assertEquals(0, b[1], 2e-3, "the belly rests on y = 0");
        // a 1.2 m snake in a flat coil is a disc of about 0.3 m, far smaller than when stretched out
        assertTrue(b[3] - b[0] < 0.4 && b[5] - b[2] < 0.4, "coil extent " + (b[3] - b[0]) + " x " + (b[5] - b[2]));
        // the profile: v rises from snout to tail, the vent where the tail begins
        SnakeMesh.Profile profile = coiled.profile();
        assertEquals(SnakeMesh.Parameters.defaults().rings(), profile.v().length);
        assertTrue(profile.ventV() > 0.6 && profile.ventV() < 0.9, "vent at v " + profile.ventV());
        assertTrue(profile.lengthAlongM() > 1.2, "the side is longer than the body's x extent");
        float[] p = m.positions();
        float[] n = m.normals();
        float[] c = coiled.centreCurvePoints();
        for (int v = 0; v < m.vertexCount(); v++) {
            assertTrue(Vec3.at(p, v).minus(Vec3.at(c, v)).dot(Vec3.at(n, v)) > 0, "vertex " + v + " normal points in");
        }
    }
}
