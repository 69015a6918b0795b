package diffract.colour;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class ColourPathTest {
    @Test
    void srgbShowsD65WhiteAsWhiteAndBlackAsBlack() {
        float[] white = ColourPath.SRGB.displayRgb(D65.whiteXyz());
        for (float c : white) {
            assertEquals(1.0f, c, 1e-3f);
        }
        float[] black = ColourPath.SRGB.displayRgb(new Xyz(0, 0, 0));
        for (float c : black) {
            assertEquals(0.0f, c, 0f);
        }
        float[] grey = ColourPath.SRGB.displayRgb(D65.whiteXyz().scaled(0.18));
        assertEquals(0.4614f, grey[1], 1e-3f);
    }

    @Test
    void srgbClipsOutOfGamutSpectralColoursPerChannel() {
        // The 520 nm spectral colour is far outside sRGB: red goes negative and is clipped to 0.
        Xyz green520 = new Xyz(Cie1931.xBar(520), Cie1931.yBar(520), Cie1931.zBar(520)).scaled(0.5);
        assertTrue(Srgb.linearFromXyz(green520)[0] < 0);
        float[] rgb = ColourPath.SRGB.displayRgb(green520);
        assertEquals(0.0f, rgb[0], 0f);
        assertTrue(rgb[1] > 0.5f && rgb[1] <= 1f);
    }

    @Test
    void thesisMapsD65WhiteToNeutralGrey() {
        float[] rgb = ColourPath.THESIS.displayRgb(D65.whiteXyz());
        assertEquals(rgb[0], rgb[1], 1e-3f);
        assertEquals(rgb[1], rgb[2], 1e-3f);
        // M's row sums are 0.17697 (CIE RGB normalisation), then gamma 2.5: 0.17697^0.4 = 0.5003.
        double[] linear = ColourPath.thesisLinearRgb(D65.whiteXyz());
        for (double c : linear) {
            assertEquals(0.17697, c, 1e-5);
        }
        assertEquals(Math.pow(0.17697, 0.4), rgb[0], 1e-4);
    }

    @Test
    void thesisMatrixIsTheInverseOfTheCie1931RgbToXyzMatrix() {
        // CIE 1931: XYZ = (1/0.17697) [[0.49, 0.31, 0.20], [0.17697, 0.81240, 0.01063], [0, 0.01, 0.99]] RGB.
        double[][] rgbToXyz = {
            {0.49 / 0.17697, 0.31 / 0.17697, 0.20 / 0.17697},
            {1, 0.81240 / 0.17697, 0.01063 / 0.17697},
            {0, 0.01 / 0.17697, 0.99 / 0.17697},
        };
        double[][] inverse = Mat3.inverse(rgbToXyz);
        double[][] m = ColourPath.thesisMatrix();
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                assertEquals(inverse[r][c], m[r][c], 5e-5, "element " + r + "," + c);
            }
        }
    }

    @Test
    void thesisClipsAndUsesGamma25() {
        float[] black = ColourPath.THESIS.displayRgb(new Xyz(0, 0, 0));
        assertEquals(0.0f, black[0], 0f);
        float[] bright = ColourPath.THESIS.displayRgb(D65.whiteXyz().scaled(100));
        assertEquals(1.0f, bright[0], 0f);
        assertEquals(1.0f, bright[2], 0f);
    }
}
