package diffract.geometry;

import diffract.util.UserInputException;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** OBJ text written by hand: faces, indices, normals, the three tangent sources and one-line errors. */
class ObjReaderTest {
    /** A unit square in z = 0 as one quad, u along x and v along y, with the thesis' tg lines along y. */
    static final String SQUARE = "# a square\n"
            + "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
            + "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
            + "tg 0 1 0\ntg 0 1 0\ntg 0 1 0\ntg 0 1 0\n"
            + "o square\ns off\n"
            + "f 1/1 2/2 3/3 4/4\n";

    @Test
    void aQuadIsTwoTrianglesWithSmoothNormals() {
        Mesh mesh = ObjReader.parse(SQUARE, "square.obj", TangentSource.fromUvs());
        assertEquals(2, mesh.triangleCount());
        assertEquals(4, mesh.vertexCount());
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3}, mesh.triangles());
        for (int v = 0; v < 4; v++) {
            assertEquals(1f, mesh.normals()[3 * v + 2], 1e-6f, "counter-clockwise faces +z");
            assertEquals(1f, mesh.tangents()[3 * v], 1e-6f, "dP/du is +x");
        }
    }

    @Test
    void explicitTangentsComeFromTheTgLines() {
        Mesh mesh = ObjReader.parse(SQUARE, "square.obj", TangentSource.explicit());
        for (int v = 0; v < 4; v++) {
            assertEquals(1f, mesh.tangents()[3 * v + 1], 1e-6f);
        }
    }

    @Test
    void projectedTangentsAreOrthogonalisedAgainstTheNormal() {
        Mesh mesh = ObjReader.parse(SQUARE, "square.obj", TangentSource.projected(1, 1, 5));
        float s = (float) Math.sqrt(0.5);
        assertEquals(s, mesh.tangents()[0], 1e-6f);
        assertEquals(s, mesh.tangents()[1], 1e-6f);
        assertEquals(0f, mesh.tangents()[2], 1e-6f);
    }

    @Test
    void negativeIndicesAndGivenNormals() {
        String text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nf -3//-1 -2//-1 -1//-1\n";
        Mesh mesh = ObjReader.parse(text, "t.obj", TangentSource.projected(1, 0, 0));
        assertEquals(1, mesh.triangleCount());
        assertFalse(mesh.hasUvs());
        assertEquals(1f, mesh.normals()[2], 1e-6f, "vn normalised");
    }

    @Test
    void aSeamInUvsSplitsAPosition() {
        String text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 0.5\n"
                + "f 1/1 2/2 3/3\nf 2/4 4/2 3/3\n";
        assertEquals(5, ObjReader.parse(text, "t.obj", TangentSource.fromUvs()).vertexCount());
    }

    private static String error(String text, TangentSource tangents) {
        UserInputException e = assertThrows(UserInputException.class, () -> ObjReader.parse(text, "m.obj", tangents));
        assertFalse(e.getMessage().contains("\n"));
        return e.getMessage();
    }

    @Test
    void errorsNameFileAndLine() {
        TangentSource uv = TangentSource.fromUvs();
        assertTrue(error("f 1 2 3\nv 0 0 0\n", uv).startsWith("m.obj:1: face before any vertex"));
        assertTrue(error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", uv)
                .startsWith("m.obj:4: vertex index 4 in face corner '4' is out of range: 3 vertices defined so far"));
        assertTrue(error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", uv).startsWith("m.obj:4: vertex index -4"));
        assertTrue(error("v 0 0 zero\n", uv).startsWith("m.obj:1: malformed number 'zero'"));
        assertTrue(error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", uv).startsWith("m.obj:4: malformed vertex index 'x'"));
        assertTrue(error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", uv).startsWith("m.obj:4: tangents from UVs need"));
        assertTrue(error("v 0 0 0\nv 1 0 0\nv 0 1 0\ntg 1 0 0\nf 1 2 3\n", TangentSource.explicit())
                .contains("1 tg lines for 3 vertices"));
        assertTrue(error("v 0 0 0\n", uv).contains("no faces"));
    }
}
