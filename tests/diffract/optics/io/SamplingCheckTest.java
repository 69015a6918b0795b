package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.optics.io.SamplingCheck.WavelengthRangeNm;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Optional;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class SamplingCheckTest {
    private static HeightField field(double pixelXUm, double pixelYUm) {
        return HeightField.of(2, 2, new double[] {0, 0.1, 0.2, 0.3}, pixelXUm, pixelYUm);
    }

    private static void assertRange(double fromNm, double toNm, Optional<WavelengthRangeNm> range) {
        assertTrue(range.isPresent(), "expected " + fromNm + "-" + toNm);
        assertEquals(fromNm, range.get().fromNm(), 1e-9);
        assertEquals(toNm, range.get().toNm(), 1e-9);
    }

    @Test
    void coarsePixelsAliasBelowTwicePixelSize() {
        Reporter.Collecting reporter = new Reporter.Collecting();

        SamplingCheck.Result result = SamplingCheck.warnAboutAliasing(field(0.3, 0.3), 380, 700, reporter);

        // 2 dH = 600 nm: 380-600 aliases at normal incidence; 4 dH = 1200 nm: 600-700 only at grazing angles
        assertRange(380, 600, result.normalX());
        assertRange(380, 600, result.normalY());
        assertRange(600, 700, result.grazingOnlyX());
        assertTrue(result.aliasesAtNormalIncidence());
        assertEquals(List.of("pixel size 0.3 um along x and y is coarser than lambda/2 for 380-600 nm: those"
                + " wavelengths alias at normal incidence; resample to <= 0.19 um"), reporter.warnings());
        assertEquals(1, reporter.infos().size());
        assertTrue(reporter.infos().get(0).contains("lambda/4 for 600-700 nm"), reporter.infos().toString());
        assertTrue(reporter.infos().get(0).contains("0.095 um"), reporter.infos().toString());
    }

    @Test
    void finePixelsSayNothing() {
        Reporter.Collecting reporter = new Reporter.Collecting();
        SamplingCheck.Result result = SamplingCheck.warnAboutAliasing(field(0.05, 0.05), 380, 780, reporter);
        assertEquals(new SamplingCheck.Result(Optional.empty(), Optional.empty(), Optional.empty(),
                Optional.empty()), result);
        assertFalse(result.aliasesAtNormalIncidence());
        assertEquals(List.of(), reporter.warnings());
        assertEquals(List.of(), reporter.infos());
    }

    @Test
    void grazingOnlyIsANoteNotAWarning() {
        Reporter.Collecting reporter = new Reporter.Collecting();
        // 2 dH = 300 nm < 380: fine at normal incidence; 4 dH = 600 nm
        SamplingCheck.Result result = SamplingCheck.warnAboutAliasing(field(0.15, 0.15), 380, 780, reporter);
        assertTrue(result.normalX().isEmpty());
        assertRange(380, 600, result.grazingOnlyX());
        assertEquals(List.of(), reporter.warnings());
        assertEquals(1, reporter.infos().size());
    }

    @Test
    void axesAreCheckedSeparately() {
        Reporter.Collecting reporter = new Reporter.Collecting();
        // x: 0.3 um aliases at normal incidence; y: 0.1 um, 2 dH = 200, 4 dH = 400: grazing only for 380-400
        SamplingCheck.Result result = SamplingCheck.warnAboutAliasing(field(0.3, 0.1), 380, 780, reporter);
        assertRange(380, 600, result.normalX());
        assertTrue(result.normalY().isEmpty());
        assertRange(380, 400, result.grazingOnlyY());
        assertEquals(1, reporter.warnings().size());
        assertTrue(reporter.warnings().get(0).contains("along x is coarser"), reporter.warnings().toString());
        assertTrue(reporter.infos().stream().anyMatch(i -> i.contains("along y") && i.contains("380-400 nm")),
                reporter.infos().toString());
    }

    @Test
    void wholeRangeAliasesWhenPixelsAreVeryCoarse() {
        Reporter.Collecting reporter = new Reporter.Collecting();
        SamplingCheck.Result result = SamplingCheck.warnAboutAliasing(field(1.0, 1.0), 380, 780, reporter);
        assertRange(380, 780, result.normalX());
        assertTrue(result.grazingOnlyX().isEmpty(), "nothing aliases at grazing angles only");
        assertEquals(List.of(), reporter.infos());
    }

    @Test
    void invalidWavelengthRangeIsAUserError() {
        assertThrows(UserInputException.class,
                () -> SamplingCheck.warnAboutAliasing(field(0.1, 0.1), 700, 380, Reporter.SILENT));
        assertThrows(UserInputException.class,
                () -> SamplingCheck.warnAboutAliasing(field(0.1, 0.1), 0, 380, Reporter.SILENT));
    }
}
