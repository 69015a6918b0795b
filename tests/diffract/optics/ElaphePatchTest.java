package diffract.optics;

import diffract.util.TestReport;
import diffract.optics.io.HeightFieldReader;
import diffract.util.Reporter;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** The measured Elaphe patch of ../shared/data (skipped in a clone without it). */
class ElaphePatchTest {
    static final Path ELAPHE = Path.of("..", "shared", "data", "patches", "elaphe-100px.png");
    /** ../shared/data/README.md: maxH 0.375 um, dH 0.0686 um; ridges along x, period along y. */
    static final double MAX_HEIGHT_UM = 0.375;
    static final double PIXEL_SIZE_UM = 0.0686;

    @Test
    void firstOrderPeriodIsTheMeasured1144Nanometres() {
        Assumptions.assumeTrue(Files.isRegularFile(ELAPHE), "no " + ELAPHE + " (only in the project's workplace)");
        HeightField patch = HeightFieldReader.load(ELAPHE, MAX_HEIGHT_UM, PIXEL_SIZE_UM, Reporter.SILENT);
        DiffractionBrdf brdf = DiffractionBrdf.create(BrdfSettings.thesis(Variant.REFERENCE), patch, null);
        // incidence plane along y (phi_i = 90 deg), where the ridge period lies; 75 degrees as the thesis did
        double periodUm = PeakFinder.meanPeriodFromFirstOrderUm(brdf, 75, 90, 380, 780, 20);
        TestReport.printf(ElaphePatchTest.class, "Elaphe patch, reference: first-order period %.2f nm (thesis: 1144.26 FLSS, 1144.18 NMM)%n",
                periodUm * 1e3);
        assertEquals(1.144, periodUm, 0.02 * 1.144, "period " + periodUm + " um");
    }
}
