package diffract.precompute;

import diffract.util.TestReport;
import diffract.optics.patches.HeightField;
import diffract.optics.NaiveDft;
import diffract.optics.spectra.TaylorTerms;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The thesis' Octave term format, written and read back. */
class ThesisFormatTest {
    /** One ulp of a float32 in [0.5, 1]: the coarsest step of a stored normalised value in [0, 1]. */
    static final double ULP_OF_ONE = Math.ulp(1.0f);

    @TempDir
    Path tmp;

    private static TaylorTerms ourTerms(int rows, int cols, int n, long seed) {
        return TaylorTermComputer.compute(NaiveDft.randomPatch(rows, cols, 0.4, 0.1, seed), n, Reporter.SILENT);
    }

    private Path writeThesis(TaylorTerms terms, String name) throws IOException {
        Path dir = tmp.resolve(name);
        ThesisFormat.write(dir, terms, new ThesisFormat.Provenance("test.png", null, null), Reporter.SILENT);
        return dir;
    }

    @ParameterizedTest
    @CsvSource({"1, 6", "4, 1", "5, 5", "6, 6", "7, 4", "8, 3"})
    void rowMapsAreInversesAndAgreeOnTheFrequency(int rows, int ignored) {
        for (int i = 0; i < rows; i++) {
            int r = ThesisLayout.nativeRowOfThesisRow(i, rows);
            assertEquals(i, ThesisLayout.thesisRowOfNativeRow(r, rows));
            // our row r holds m_y = r - floor(R/2); the script's row i holds the same frequency modulo R
            assertEquals(0, Math.floorMod(ThesisLayout.frequencyOfThesisRow(i, rows) - (r - rows / 2), rows));
        }
        assertEquals(rows % 2 == 0 ? 1 : 0, ThesisLayout.rowOffset(rows));
    }

    /**
     * (a) and item 3: write, read back, compare with the float32 terms. Read-back value x' of a component is
     * min + v range in double, v the stored float32 (at most half an ulp of 1.0f away from the exact (x - min) /
     * range), then the phase of ThesisLayout is undone in double, mixing the Re and Im errors, and the result is
     * rounded once to float32. So |x' - x| <= (rangeRe + rangeIm) ulp(1.0f) / 2 + ulp(x) / 2; we assert the
     * bound with whole ulps ("1 ulp of the stored normalised value", plus one ulp of the result).
     */
    @ParameterizedTest
    @CsvSource({"7, 5", "9, 4", "6, 9"})
    void readBackEqualsOurTermsWithinOneUlpOfTheStoredNormalisedValue(int rows, int cols) throws IOException {
        TaylorTerms terms = ourTerms(rows, cols, 8, rows * 100L + cols);
        Path dir = writeThesis(terms, "t" + rows + "x" + cols);
        TaylorTerms back = ThesisFormat.read(dir, ThesisFormat.HeightUnit.AUTO, Reporter.SILENT);
        assertEquals(rows, back.rows());
        assertEquals(cols, back.cols());
        assertEquals(terms.pixelSizeXUm(), back.pixelSizeXUm());
        assertEquals(terms.maxAbsHeightUm(), back.maxAbsHeightUm());
        double worstRatio = compareWithinNormalisationBound(terms, back, readExtrema(dir), 0);
        TestReport.printf(ThesisFormatTest.class, Locale.ROOT, "thesis round trip %dx%d: worst |error| / ((rangeRe + rangeIm) ulp(1f)/2)"
                + " = %.3f%n", rows, cols, worstRatio);
    }

    /** Same texel = same frequency: the read-back texel (r, c) is ifft2((i h)^n) at (c - C/2, r - R/2). */
    @Test
    void readBackTexelsHoldOurFrequencies() throws IOException {
        int rows = 7;
        int cols = 5;
        HeightField h = NaiveDft.randomPatch(rows, cols, 0.4, 0.1, 99);
        TaylorTerms back = ThesisFormat.read(writeThesis(TaylorTermComputer.compute(h, 4, Reporter.SILENT), "f"),
                ThesisFormat.HeightUnit.AUTO, Reporter.SILENT);
        for (int n = 0; n <= 4; n++) {
            double[] power = NaiveDft.powerIH(h, n);
            for (int r = 0; r < rows; r++) {
                for (int c = 0; c < cols; c++) {
                    double[] exact = NaiveDft.inverseAt(power, rows, cols, c - cols / 2, r - rows / 2);
                    assertEquals(exact[0], back.re(n, r, c), 1e-6, "Re term " + n + " texel " + r + "," + c);
                    assertEquals(exact[1], back.im(n, r, c), 1e-6, "Im term " + n + " texel " + r + "," + c);
                }
            }
        }
    }

    /** A folder as the original script leaves it (no diffract.json): extrema from the text, unit detected. */
    @Test
    void scriptFolderWithoutExtrasReadsTheSameAndSaysWhichUnit() throws IOException {
        TaylorTerms terms = ourTerms(6, 7, 10, 5);
        Path dir = writeThesis(terms, "script");
        Files.delete(dir.resolve(ThesisFormat.EXTRAS_FILE));
        Reporter.Collecting reporter = new Reporter.Collecting();
        TaylorTerms back = ThesisFormat.read(dir, ThesisFormat.HeightUnit.AUTO, reporter);
        assertTrue(reporter.infos().stream().anyMatch(s -> s.contains("heights taken as micrometres (detected")),
                reporter.infos().toString());
        assertEquals(terms.pixelSizeXUm(), back.pixelSizeXUm(), 1e-15);
        // the text keeps 35 decimals: 5e-36 more per extremum, far below the float32 steps
        compareWithinNormalisationBound(terms, back, ThesisExtrema.read(dir.resolve(ThesisFormat.EXTREMA_FILE)).terms(),
                1e-35);
        double trueMax = terms.maxAbsHeightUm();
        assertTrue(back.maxAbsHeightUm() >= trueMax, "the estimate is an upper bound: " + back.maxAbsHeightUm());
        assertTrue(back.maxAbsHeightUm() <= trueMax * Math.pow(42, 1.0 / 10) * 1.000001, "and within the bracket");
        assertTrue(reporter.infos().stream().anyMatch(s -> s.contains("max|h| not stored")));
    }

    /** Older script outputs used metres: the images are the same, term n's extrema scale by 1e-6^n. */
    @Test
    void metreFoldersAreDetectedAndScaledToMicrometres() throws IOException {
        TaylorTerms um = ourTerms(5, 6, 3, 8);
        float[][] metres = new float[4][];
        for (int n = 0; n <= 3; n++) {
            metres[n] = um.termData(n);
            for (int i = 0; i < metres[n].length; i++) {
                metres[n][i] = (float) (metres[n][i] * Math.pow(1e-6, n));
            }
        }
        TaylorTerms inMetres = new TaylorTerms(5, 6, 0.1, 0.1, um.maxAbsHeightUm() * 1e-6, metres);
        Path dir = writeThesis(inMetres, "metres");
        Files.delete(dir.resolve(ThesisFormat.EXTRAS_FILE));
        Reporter.Collecting reporter = new Reporter.Collecting();
        TaylorTerms back = ThesisFormat.read(dir, ThesisFormat.HeightUnit.AUTO, reporter);
        assertTrue(reporter.infos().stream().anyMatch(s -> s.contains("heights taken as metres (detected")));
        for (int n = 0; n <= 3; n++) {
            float[] expected = um.termData(n);
            float[] got = back.termData(n);
            double scale = maxAbs(expected);
            for (int i = 0; i < got.length; i++) {
                assertEquals(expected[i], got[i], 5e-7 * scale, "term " + n + " value " + i);
            }
        }
        // asked explicitly: no detection
        Reporter.Collecting asked = new Reporter.Collecting();
        ThesisFormat.read(dir, ThesisFormat.HeightUnit.METRES, asked);
        assertTrue(asked.infos().stream().anyMatch(s -> s.contains("heights taken as metres (as asked")));
    }

    @Test
    void onlyPixelSizesThatReallyDifferAreWarnedAbout() throws IOException {
        TaylorTerms terms = ourTerms(4, 5, 2, 3);
        // 0.7 um over 7 rows and 0.1 um per column are the same size, computed two ways (last bits differ)
        double rowStepUm = 0.7 / 7;
        assertNotEquals(0.1, rowStepUm, 0.0);
        TaylorTerms sameSize = new TaylorTerms(4, 5, 0.1, rowStepUm, terms.maxAbsHeightUm(), termArrays(terms));
        Reporter.Collecting same = new Reporter.Collecting();
        ThesisFormat.write(tmp.resolve("same"), sameSize, new ThesisFormat.Provenance("x", null, null), same);
        assertEquals(List.of(), same.warnings());
        TaylorTerms otherSize = new TaylorTerms(4, 5, 0.1, 0.1001, terms.maxAbsHeightUm(), termArrays(terms));
        Reporter.Collecting other = new Reporter.Collecting();
        ThesisFormat.write(tmp.resolve("other"), otherSize, new ThesisFormat.Provenance("x", null, null), other);
        assertEquals(1, other.warnings().size(), other.warnings().toString());
        assertTrue(other.warnings().get(0).contains("y is 0.100100 um"), other.warnings().get(0));
    }

    private static float[][] termArrays(TaylorTerms terms) {
        float[][] data = new float[terms.highestOrder() + 1][];
        for (int n = 0; n <= terms.highestOrder(); n++) {
            data[n] = terms.termData(n);
        }
        return data;
    }

    @Test
    void anAmbiguousUnitIsRefusedWithTheOptionToPass() throws IOException {
        // RMS height 2e-5: 20 um if metres, 0.02 nm if micrometres; neither is a nanostructure
        HeightField h = NaiveDft.randomPatch(4, 5, 1, 0.1, 3);
        double[] scaled = h.heightsUm();
        double rms = Math.sqrt(Arrays.stream(scaled).map(v -> v * v).average().orElseThrow());
        for (int i = 0; i < scaled.length; i++) {
            scaled[i] *= 2e-5 / rms;
        }
        TaylorTerms terms = TaylorTermComputer.compute(HeightField.of(4, 5, scaled, 0.1), 2, Reporter.SILENT);
        Path dir = writeThesis(terms, "ambiguous");
        Files.delete(dir.resolve(ThesisFormat.EXTRAS_FILE));
        UserInputException e = assertThrows(UserInputException.class,
                () -> ThesisFormat.read(dir, ThesisFormat.HeightUnit.AUTO, Reporter.SILENT));
        assertTrue(e.getMessage().contains("give the height unit, m or um"), e.getMessage());
        ThesisFormat.read(dir, ThesisFormat.HeightUnit.MICROMETRES, Reporter.SILENT);
    }

    @Test
    void extremaTextIsFixedPointWith35DecimalsAndGuarded() {
        assertEquals("0.00000009999999999999999547481118259", ThesisExtrema.format(1e-7)); // as C's printf
        assertEquals("-1.50000000000000000000000000000000000", ThesisExtrema.format(-1.5));
        // "0." and 35 decimals already exceed the width 36: the width never pads
        assertEquals("0." + "0".repeat(35), ThesisExtrema.format(0.0));
        ThesisExtrema.Channel flat = ThesisExtrema.Channel.of(new double[] {3e-36, 0, -2e-36, 0}, 0);
        assertEquals(0.0, flat.min());
        assertEquals(1.0, flat.range());
    }

    @Test
    void filesHaveTheScriptLayout() throws IOException {
        TaylorTerms terms = ourTerms(3, 4, 2, 1);
        Path dir = writeThesis(terms, "layout");
        assertEquals(8 + 12 * 3 * 4, Files.size(dir.resolve("AmpReIm2.txt")));
        assertEquals(3 * 8, Files.readAllLines(dir.resolve("extrema.txt")).size());
        assertFalse(Files.exists(dir.resolve("AmpReIm3.txt")));
        java.util.List<String> parameters = Files.readAllLines(dir.resolve("paramters.txt"));
        assertEquals(java.util.List.of("380", "780", "2", "4", "3", "5", "100", "test.png"), parameters);
        ThesisRecipe.TermFile file = ThesisRecipe.TermFile.read(dir.resolve("AmpReIm1.txt"));
        assertEquals(4, file.width());
        assertEquals(3, file.height());
        for (int i = 0; i < 12; i++) {
            assertEquals(0.5f, file.values()[3 * i + 2]);
        }
        // a shorter rewrite removes the stale term files
        ThesisFormat.write(dir, ourTerms(3, 4, 1, 1), new ThesisFormat.Provenance("x", null, null), Reporter.SILENT);
        assertFalse(Files.exists(dir.resolve("AmpReIm2.txt")));
    }

    // (d) one-line errors that name the file

    @Test
    void aMissingTermFileIsNamed() throws IOException {
        Path dir = writeThesis(ourTerms(4, 5, 3, 2), "missing");
        Files.delete(dir.resolve("AmpReIm2.txt"));
        assertOneLineError(dir, "AmpReIm2.txt", "missing");
    }

    @Test
    void aTruncatedTermFileIsNamed() throws IOException {
        Path dir = writeThesis(ourTerms(4, 5, 3, 2), "truncated");
        Path file = dir.resolve("AmpReIm1.txt");
        byte[] bytes = Files.readAllBytes(file);
        Files.write(file, Arrays.copyOf(bytes, bytes.length - 7));
        assertOneLineError(dir, "AmpReIm1.txt", "truncated");
    }

    @Test
    void termsOfDifferentSizesAreNamed() throws IOException {
        Path dir = writeThesis(ourTerms(4, 5, 3, 2), "sizes");
        Path other = writeThesis(ourTerms(5, 4, 3, 2), "other");
        Files.copy(other.resolve("AmpReIm3.txt"), dir.resolve("AmpReIm3.txt"),
                java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        assertOneLineError(dir, "AmpReIm3.txt", "4 x 5 texels but AmpReIm0.txt is 5 x 4");
    }

    @Test
    void foldersWithoutTermsAreRefusedByTermFolders() throws IOException {
        Path empty = Files.createDirectories(tmp.resolve("empty"));
        UserInputException e = assertThrows(UserInputException.class, () -> TermFolders.read(empty, Reporter.SILENT));
        assertTrue(e.getMessage().contains("holds no precomputed terms"), e.getMessage());
    }

    private static void assertOneLineError(Path dir, String fileName, String words) {
        UserInputException e = assertThrows(UserInputException.class,
                () -> TermFolders.read(dir, Reporter.SILENT));
        assertTrue(e.getMessage().contains(dir.resolve(fileName).toString()), e.getMessage());
        assertTrue(e.getMessage().contains(words), e.getMessage());
        assertFalse(e.getMessage().contains("\n"), "one line: " + e.getMessage());
    }

    private static java.util.List<ThesisExtrema.Term> readExtrema(Path dir) {
        return ThesisExtrema.read(dir.resolve(ThesisFormat.EXTREMA_FILE)).terms();
    }

    /** Asserts the bound of the round-trip test; returns the worst error in half-ulp units of the bound. */
    static double compareWithinNormalisationBound(TaylorTerms expected, TaylorTerms got,
                                                  java.util.List<ThesisExtrema.Term> extrema, double slack) {
        double worst = 0;
        for (int n = 0; n < expected.termCount(); n++) {
            ThesisExtrema.Term t = extrema.get(n);
            double halfUlpStep = (t.re().range() + t.im().range()) * ULP_OF_ONE / 2;
            for (int r = 0; r < expected.rows(); r++) {
                for (int c = 0; c < expected.cols(); c++) {
                    float[] want = {expected.re(n, r, c), expected.im(n, r, c)};
                    float[] have = {got.re(n, r, c), got.im(n, r, c)};
                    for (int k = 0; k < 2; k++) {
                        double error = Math.abs((double) have[k] - want[k]);
                        double bound = 2 * halfUlpStep + Math.ulp(want[k]) + slack;
                        assertTrue(error <= bound, String.format(Locale.ROOT, "term %d texel (%d,%d) %s: %g vs %g, "
                                + "error %.3g > bound %.3g", n, r, c, k == 0 ? "Re" : "Im", have[k], want[k], error, bound));
                        worst = Math.max(worst, error / halfUlpStep);
                    }
                }
            }
        }
        return worst;
    }

    static double maxAbs(float[] values) {
        double m = 0;
        for (float v : values) {
            m = Math.max(m, Math.abs(v));
        }
        return m;
    }
}
