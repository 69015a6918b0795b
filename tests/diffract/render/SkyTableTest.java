package diffract.render;

import diffract.jrtr.textures.FloatTexture3D;
import diffract.lighting.ExtendedLight;
import diffract.optics.BakedGrid;
import diffract.optics.Variant;
import diffract.optics.illumination.LightSource;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The tables the staged baked surface reads for its environment lights: a uniform table stays uniform inside (the
 * spread keeps the BRDF's integral), a single sample spreads with the light's variance once the lookup's own
 * interpolation is counted, each light gets its own width, and w is sampled finely and linearly.
 */
class SkyTableTest {
    private static final int N = 33;      // table samples per (u, v) axis: spacing 0.125
    private static final int NW = 3;
    private static final double TABLE_SIGMA_RAD = 0.05;

    @Test
    void aUniformTableStaysUniformAwayFromItsEdges() {
        float[] rgb = new float[3 * N * N * NW];
        java.util.Arrays.fill(rgb, 1f);
        SkyTable sky = SkyTable.of(table(rgb), List.of(light(60, 0.7)), TABLE_SIGMA_RAD);
        int mid = sky.side() / 2;
        for (int m = 0; m < sky.wSamples(); m++) {
            assertEquals(1.0, sky.xyzAt(0, mid, mid, m)[1], 1e-4, "the centre of slice " + m);
        }
        // beyond |u| = 2 the table is zero (unreachable): the spread falls towards the edges
        float centre = sky.xyzAt(0, mid, mid, 0)[0];
        float edge = sky.xyzAt(0, 0, mid, 0)[0];
        assertTrue(edge < 0.7 * centre && edge > 0.4 * centre, "edge " + edge + " against centre " + centre);
    }

    @Test
    void aSingleSampleSpreadsWithTheLightsVarianceAsTheLookupSeesIt() {
        double du = (BakedGrid.U_MAX - BakedGrid.U_MIN) / (N - 1);
        for (double diameterDeg : new double[] {30, 60, 90}) {
            float[] rgb = new float[3 * N * N * NW];
            int centre = N / 2; // u = v = 0
            for (int w = 0; w < NW; w++) {
                rgb[3 * (centre + N * (centre + N * w)) + 1] = (float) (1 / (du * du)); // unit integral
            }
            SkyTable sky = SkyTable.of(table(rgb), List.of(light(diameterDeg, 0.3)), TABLE_SIGMA_RAD);
            int side = sky.side();
            double step = (BakedGrid.U_MAX - BakedGrid.U_MIN) / (side - 1);
            double mass = 0;
            double second = 0;
            for (int j = 0; j < side; j++) {
                double u = BakedGrid.U_MIN + j * step;
                for (int l = 0; l < side; l++) {
                    double value = sky.xyzAt(0, j, l, 2)[1] * step * step;
                    mass += value;
                    second += value * u * u;
                }
            }
            double sigma = LightSource.sigmaRadOf(diameterDeg);
            double light = sigma * sigma * (1 + SkyTable.MEAN_COS2_THETA_I) / 2;
            // the lookup adds the bilinear tent of the grid (step^2 / 6), the table's cell stands for du^2 / 12
            double seen = second / mass + step * step / 6 + du * du / 12;
            assertEquals(1.0, mass, 2e-3, diameterDeg + " degrees: the sample's integral is kept");
            assertEquals(light - TABLE_SIGMA_RAD * TABLE_SIGMA_RAD, seen, 0.02 * light,
                    diameterDeg + " degrees: the light's variance beyond the table's own");
        }
    }

    @Test
    void eachLightHasItsOwnSlicesAndWIsLinearBetweenTheTablesSamples() {
        float[] rgb = new float[3 * N * N * NW];
        for (int w = 0; w < NW; w++) {
            for (int t = 0; t < N * N; t++) {
                rgb[3 * (t + N * N * w) + 2] = w; // Z = the w sample's index
            }
        }
        SkyTable sky = SkyTable.of(table(rgb), List.of(light(40, 0.9), light(80, 0.2)), TABLE_SIGMA_RAD);
        assertEquals(SkyTable.W_OVERSAMPLING * (NW - 1) + 1, sky.wSamples());
        assertEquals(2, sky.lights());
        int mid = sky.side() / 2;
        for (int k = 0; k < 2; k++) {
            for (int m = 0; m < sky.wSamples(); m++) {
                assertEquals((double) m / SkyTable.W_OVERSAMPLING, sky.xyzAt(k, mid, mid, m)[2], 1e-4);
            }
        }
        // the wider light reaches further towards the table's edge, where the narrower one has fallen off less
        assertTrue(sky.xyzAt(1, 0, mid, 4)[2] < sky.xyzAt(0, 0, mid, 4)[2]);
    }

    @Test
    void theGridFollowsTheNarrowestLightWithinItsLimits() {
        assertEquals(SkyTable.MIN_SIDE, SkyTable.side(1.0, 512));
        assertEquals(32, SkyTable.side(0.25, 512)); // 1.5 x 4 / 0.25 + 1 = 25 samples needed
        assertEquals(SkyTable.MAX_SIDE, SkyTable.side(0.001, 512));
        assertEquals(64, SkyTable.side(0.001, 64), "never finer than the table");
    }

    private static BakedTable table(float[] rgb) {
        return new BakedTable(new BakedGrid(N, NW), rgb, FloatTexture3D.Precision.FLOAT32, 0, Variant.LOBES, 0);
    }

    private static ExtendedLight light(double diameterDeg, double elevationY) {
        double y = elevationY;
        double x = Math.sqrt(1 - y * y);
        return new ExtendedLight(new double[] {x, y, 0}, new double[] {0.1, 0.1, 0.1}, 0.1, diameterDeg);
    }
}
