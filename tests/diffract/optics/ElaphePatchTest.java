package diffract.optics;

import diffract.optics.io.HeightFieldReader;
import diffract.optics.patches.HeightField;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** The measured Elaphe patch shipped in assets/patches (its README gives source and parameters). */
class ElaphePatchTest {
    static final Path ELAPHE = Path.of("assets", "patches", "elaphe-100px.png");
    static final Path ELAPHE_GWY = Path.of("assets", "patches", "elaphe-100px.gwy");
    /** assets/patches/README.md: maxH 0.375 um, dH 0.0686 um; ridges along x, period along y. */
    static final double MAX_HEIGHT_UM = 0.375;
    static final double PIXEL_SIZE_UM = 0.0686;

    @Test
    void firstOrderPeriodIsTheMeasured1144Nanometres() {
        HeightField patch = HeightFieldReader.load(ELAPHE, MAX_HEIGHT_UM, PIXEL_SIZE_UM, Reporter.SILENT);
        DiffractionBrdf brdf = DiffractionBrdf.create(BrdfSettings.thesis(Variant.REFERENCE), patch, null);
        // incidence plane along y (phi_i = 90 deg), where the ridge period lies; 75 degrees as the thesis did
        double periodUm = PeakFinder.meanPeriodFromFirstOrderUm(brdf, 75, 90, 380, 780, 20);
        TestReport.printf(ElaphePatchTest.class, "Elaphe patch, reference: first-order period %.2f nm (thesis: 1144.26 FLSS, 1144.18 NMM)%n",
                periodUm * 1e3);
        assertEquals(1.144, periodUm, 0.02 * 1.144, "period " + periodUm + " um");
    }

    @Test
    void theGwyddionFileHoldsThePicturesHeightsAtItsSize() {
        HeightField png = HeightFieldReader.load(ELAPHE, MAX_HEIGHT_UM, PIXEL_SIZE_UM, Reporter.SILENT);
        HeightField gwy = HeightFieldReader.load(ELAPHE_GWY, null, null, Reporter.SILENT);
        assertEquals(100, gwy.rows());
        assertEquals(100, gwy.cols());
        assertEquals(PIXEL_SIZE_UM, gwy.pixelSizeXUm(), 1e-15);
        assertEquals(PIXEL_SIZE_UM, gwy.pixelSizeYUm(), 1e-15);
        // grey 21..244 of the picture: 0.0309 to 0.359 um before the mean is taken off
        assertEquals((244 - 21) / 255.0 * MAX_HEIGHT_UM, gwy.maxHeightUm() - gwy.minHeightUm(), 1e-12);
        for (int r = 0; r < 100; r++) {
            for (int c = 0; c < 100; c++) {
                assertEquals(png.heightUm(r, c), gwy.heightUm(r, c), 1e-12, "row " + r + ", column " + c);
            }
        }
    }
}
