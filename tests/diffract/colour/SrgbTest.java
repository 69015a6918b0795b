package diffract.colour;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class SrgbTest {
    // IEC 61966-2-1:1999, XYZ -> linear sRGB, as printed (4 decimals).
    private static final double[][] IEC_MATRIX = {
        {3.2406, -1.5372, -0.4986},
        {-0.9689, 1.8758, 0.0415},
        {0.0557, -0.2040, 1.0570},
    };

    @Test
    void derivedMatrixMatchesIecsRoundedOne() {
        double[][] m = Srgb.xyzToLinearMatrix();
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                assertEquals(IEC_MATRIX[r][c], m[r][c], 1e-3, "element " + r + "," + c);
            }
        }
        // The familiar double-precision value from the primaries and (0.3127, 0.3290).
        assertEquals(3.2409699, m[0][0], 1e-7);
        double[][] toXyz = Srgb.linearToXyzMatrix();
        assertEquals(0.2126390, toXyz[1][0], 1e-7); // luminance of the red primary (Rec. 709 0.2126)
    }

    @Test
    void roundTripsThroughXyz() {
        double[][] samples = {{1, 1, 1}, {0.2, 0.7, -0.1}, {3, 0, 0.5}, {0, 0, 0}};
        for (double[] rgb : samples) {
            double[] back = Srgb.linearFromXyz(Srgb.xyzFromLinear(rgb));
            for (int c = 0; c < 3; c++) {
                assertEquals(rgb[c], back[c], 1e-12);
            }
        }
        assertThrows(IllegalArgumentException.class, () -> Srgb.xyzFromLinear(new double[] {1, 2}));
    }

    @Test
    void whitesMapToOne() {
        double[] exact = Srgb.linearFromXyz(Srgb.whiteXyz());
        double[] spectral = Srgb.linearFromXyz(D65.whiteXyz());
        for (int c = 0; c < 3; c++) {
            assertEquals(1.0, exact[c], 1e-12);
            assertEquals(1.0, spectral[c], 1e-3);
        }
    }

    @Test
    void curveRoundTripsOnAGrid() {
        for (int i = 0; i <= 100_000; i++) {
            double x = i / 100_000.0;
            assertEquals(x, Srgb.encode(Srgb.decode(x)), 1e-12, "at " + x);
        }
        // Around the break, where the two branches meet.
        for (double x = 0.040449; x <= 0.040451; x += 1e-10) {
            assertEquals(x, Srgb.encode(Srgb.decode(x)), 1e-12, "at " + x);
        }
    }

    @Test
    void curveIsContinuousAtTheBreakAndKnownAtMidGrey() {
        double below = Srgb.encode(0.0031308);
        double above = Srgb.encode(Math.nextUp(0.0031308));
        // IEC's rounded constants leave a jump of 2.9e-8 there.
        assertEquals(below, above, 1e-7);
        assertEquals(0.040449936, below, 1e-12);
        assertEquals(0.4613561295, Srgb.encode(0.18), 1e-9);
        assertEquals(0.4614, Srgb.encode(0.18), 1e-4);
        assertEquals(0.18, Srgb.decode(0.4613561295), 1e-10);
        assertEquals(0.5, Srgb.encode(Srgb.decode(0.5)), 1e-15);
    }

    @Test
    void encodeClampsOutOfGamutValues() {
        assertEquals(0.0, Srgb.encode(-0.3));
        assertEquals(1.0, Srgb.encode(1.7));
        assertEquals(1.0, Srgb.encode(1.0), 1e-15);
        assertTrue(Double.isNaN(Srgb.encode(Double.NaN)));
    }
}
