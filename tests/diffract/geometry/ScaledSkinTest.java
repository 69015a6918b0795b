package diffract.geometry;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The scale frame: normals unit and facing out, each texel's long axis the axis of the scale it shows (turned by
 * that scale's own yaw only), every point of the skin covered by a scale, the u seam invisible, scale counts as
 * the species' taxonomy says.
 */
class ScaledSkinTest {
    static ScaledSkin skin(SnakeSpecies species, SnakeMesh.RidgeDirection ridges) {
        SnakeMesh snake = SnakeMesh.generate(SnakeMesh.Parameters.defaults().withResolution(160, 32));
        return new ScaledSkin(new ScaleLattice(species.scales()), snake.profile(), ridges);
    }

    @ParameterizedTest
    @EnumSource(SnakeSpecies.class)
    void everyPointOfTheSkinLiesOnAScaleAndNormalsAreUnitAndFaceOut(SnakeSpecies species) {
        ScaledSkin s = skin(species, SnakeMesh.RidgeDirection.ALONG_BODY);
        int uncovered = 0;
        double worstUnit = 0;
        double lowestNz = 1;
        for (int i = 0; i < 400; i++) {
            for (int j = 0; j < 1000; j++) {
                double u = (i + 0.37) / 400;
                double v = (j + 0.61) / 1000;
                if (s.visible(u, v).covered()) {
                    uncovered++;
                }
                double[] f = s.frameAt(u, v);
                worstUnit = Math.max(worstUnit, Math.abs(Math.sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]) - 1));
                lowestNz = Math.min(lowestNz, f[2]);
                worstUnit = Math.max(worstUnit, Math.abs(Math.hypot(f[3], f[4]) - 1));
            }
        }
        assertEquals(0, uncovered, "points that no scale's footprint holds (cracks)");
        assertTrue(worstUnit < 1e-12, "| |n| - 1 | and | |axis| - 1 | up to " + worstUnit);
        // tilt 6-7 degrees, dome 12-18, jitter 4-5: no visible normal lies beyond ~60 degrees from the skin's
        assertTrue(lowestNz > 0.5, "the most tilted normal has n.z = " + lowestNz);
    }

    @ParameterizedTest
    @EnumSource(SnakeSpecies.class)
    void theTangentFollowsEachScalesOwnLongAxis(SnakeSpecies species) {
        ScaledSkin s = skin(species, SnakeMesh.RidgeDirection.ALONG_BODY);
        ScaleLattice lattice = s.lattice();
        double yawSigma = Math.toRadians(species.scales().yawJitterDeg());
        double largest = 0;
        int scalesSeen = 0;
        for (int j = 0; j < 2000; j++) {
            double v = 0.2 + 0.5 * (j + 0.5) / 2000;
            double u = 0.5 + 0.3 * Math.sin(j * 0.37); // over the back and flanks
            ScaleLattice.Hit hit = s.visible(u, v);
            double[] f = s.frameAt(u, v);
            // the axis is the scale's: the same at every point of one scale, turned from "along the body" by
            // that scale's yaw, which stays within 5 sigma
            double yaw = Math.atan2(f[4], f[3]);
            double[] centreFrame = lattice.frame(hit, s.rowWidthM(v), s.rowLengthM(v));
            assertEquals(Math.atan2(centreFrame[4], centreFrame[3]), yaw, 1e-12);
            double[] elsewhere = lattice.frame(new ScaleLattice.Hit(hit.ventral(), hit.row(), hit.index(), 0, 0, 0,
                    false), s.rowWidthM(v), s.rowLengthM(v));
            assertEquals(elsewhere[3], f[3], 1e-12, "one axis per scale");
            largest = Math.max(largest, Math.abs(yaw));
            scalesSeen++;
        }
        assertTrue(largest < 5 * yawSigma, "largest yaw " + Math.toDegrees(largest));
        assertTrue(largest > 0.5 * yawSigma, "the axes do vary from scale to scale: largest yaw " + Math.toDegrees(largest));
        assertTrue(scalesSeen > 0);
    }

    @Test
    void aroundTheBodyTheFrameIsTurnedByNinetyDegreesAndTheAxisKept() {
        ScaledSkin along = skin(SnakeSpecies.XENOPELTIS_UNICOLOR, SnakeMesh.RidgeDirection.ALONG_BODY);
        ScaledSkin around = skin(SnakeSpecies.XENOPELTIS_UNICOLOR, SnakeMesh.RidgeDirection.AROUND_BODY);
        for (double v = 0.1; v < 0.9; v += 0.013) {
            double[] a = along.frameAt(0.47, v);
            double[] b = around.frameAt(0.47, v);
            // tangent = around, bitangent = -along
            assertEquals(a[1], b[0], 1e-12);
            assertEquals(-a[0], b[1], 1e-12);
            assertEquals(a[3], b[3], 1e-12);
            assertEquals(a[4], b[4], 1e-12);
        }
    }

    @ParameterizedTest
    @EnumSource(SnakeSpecies.class)
    void theUSeamOnTheBellyIsNoSeam(SnakeSpecies species) {
        ScaledSkin s = skin(species, SnakeMesh.RidgeDirection.ALONG_BODY);
        int width = 512;
        for (int j = 0; j < 500; j++) {
            double v = (j + 0.5) / 500;
            // the same point reached from both sides of u = 0 gives the same scale and frame
            double[] left = s.frameAt(1e-9, v);
            double[] right = s.frameAt(1 - 1e-9 + 1, v);
            for (int k = 0; k < 5; k++) {
                assertEquals(left[k], right[k], 1e-6);
            }
            // neighbouring texels across the seam differ no more than neighbours elsewhere on the same plate
            double[] last = s.frameAt((width - 0.5) / width, v);
            double[] first = s.frameAt(0.5 / width, v);
            double[] inner = s.frameAt(1.5 / width, v);
            double acrossSeam = Math.abs(last[0] - first[0]) + Math.abs(last[1] - first[1]);
            double inside = Math.abs(inner[0] - first[0]) + Math.abs(inner[1] - first[1]);
            assertTrue(acrossSeam <= 2 * inside + 1e-9, "seam step " + acrossSeam + " vs " + inside + " at v " + v);
        }
    }

    @ParameterizedTest
    @EnumSource(SnakeSpecies.class)
    void rowsAndVentralsNumberAsTheSpeciesSays(SnakeSpecies species) {
        ScaledSkin s = skin(species, SnakeMesh.RidgeDirection.ALONG_BODY);
        SnakeMesh snake = SnakeMesh.generate(SnakeMesh.Parameters.defaults().withResolution(160, 32));
        assertEquals(species.scales().ventralScales(), s.q(snake.profile().ventV()), 1e-6);
        // around the back at mid-body: count changes of dorsal row
        java.util.Set<Integer> rows = new java.util.HashSet<>();
        int ventralTexels = 0;
        for (int i = 0; i < 2000; i++) {
            for (int j = 0; j < 8; j++) {
                // the rear edges of one row's scales cover the next row's fronts: a ring shows every other row,
                // a few rings along show them all
                ScaleLattice.Hit hit = s.visible((i + 0.5) / 2000, 0.5 + j * 0.001);
                if (hit.ventral()) {
                    ventralTexels++;
                } else {
                    rows.add(hit.row());
                }
            }
        }
        assertEquals(species.scales().dorsalRows(), rows.size());
        assertEquals(species.scales().ventralFraction(), ventralTexels / 16000.0, 1e-3);
        // mid-body scales are millimetres: a corn snake's dorsal row is 2-5 mm long
        assertTrue(s.rowLengthM(0.5) > 2e-3 && s.rowLengthM(0.5) < 8e-3, "row length " + s.rowLengthM(0.5));
    }

    @Test
    void theFrameMapHoldsTheFramesRowByRowFromTheSnout() {
        ScaledSkin s = skin(SnakeSpecies.ELAPHE_GUTTATA, SnakeMesh.RidgeDirection.ALONG_BODY);
        float[] map = s.frameMap(64, 256);
        for (int row : new int[] {0, 100, 255}) {
            for (int c : new int[] {0, 31, 63}) {
                double[] f = s.frameAt((c + 0.5) / 64, (row + 0.5) / 256);
                int k = 4 * (row * 64 + c);
                assertEquals(f[0], map[k], 1e-6);
                assertEquals(f[1], map[k + 1], 1e-6);
                assertEquals(f[3], map[k + 2], 1e-6);
                assertEquals(f[4], map[k + 3], 1e-6);
            }
        }
        assertFalse(java.util.Arrays.equals(map, new float[map.length]));
    }
}
