package diffract.precompute;

import diffract.util.TestReport;
import diffract.optics.patches.HeightField;
import diffract.optics.NaiveDft;
import diffract.optics.spectra.TaylorTerms;
import diffract.util.Reporter;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * (b) Our terms written in the thesis format equal an independent computation of the script's recipe: a literal
 * Java restatement ({@link ThesisRecipe}, always) and an Octave script ({@code precompute/compute_fft_images.m},
 * when {@code octave} is on the PATH).
 *
 * <p>Tolerance, "float32 rounding": our file comes from the float32 terms (each component within half an ulp
 * of its double value), rotated by the row's phase in double, normalised and rounded to float32; the reference is
 * double throughout. So a de-normalised value may differ by |x| ulp(1f) (both components' roundings, mixed by the
 * phase) plus half an ulp of the stored value times the range, on each side. We compare de-normalised values with
 * 2 ulp(1f) (scale + range), scale being the term's largest |component|: noise-only channels (Im of term 0, whose
 * range is rounding noise of 1e-17) then compare on the term's scale, where they are zero.
 */
class ThesisRecipeTest {
    @TempDir
    Path tmp;

    @ParameterizedTest
    @CsvSource({"5, 7", "6, 8", "4, 9", "7, 6", "1, 5"})
    void ourThesisFilesEqualTheRecipeRestatedInJava(int rows, int cols) throws IOException {
        HeightField h = NaiveDft.randomPatch(rows, cols, 0.5, 0.1, 1000L + 17 * rows + cols);
        int highestOrder = 6;
        Path dir = tmp.resolve("java" + rows + "x" + cols);
        ThesisFormat.write(dir, TaylorTermComputer.compute(h, highestOrder, Reporter.SILENT),
                new ThesisFormat.Provenance("h", null, null), Reporter.SILENT);
        List<ThesisExtrema.Term> extrema = ThesisExtrema.read(dir.resolve(ThesisFormat.EXTREMA_FILE)).terms();
        double worst = 0;
        for (int n = 0; n <= highestOrder; n++) {
            double[][] reference = ThesisRecipe.scriptImage(h, n);
            ThesisRecipe.TermFile file = ThesisRecipe.TermFile.read(dir.resolve(ThesisFormat.termFileName(n)));
            assertEquals(cols, file.width());
            assertEquals(rows, file.height());
            worst = Math.max(worst, compare(reference, file, extrema.get(n), rows, cols, "term " + n));
        }
        TestReport.printf(ThesisRecipeTest.class, Locale.ROOT, "thesis recipe (Java) %dx%d: worst |difference| = %.3f ulp(1f) x (scale + range)%n",
                rows, cols, worst);
    }

    @Test
    void ourThesisFilesEqualTheOctaveScript() throws Exception {
        Assumptions.assumeTrue(octaveOnPath(), "octave is not on the PATH");
        for (int[] size : new int[][] {{5, 7}, {6, 8}}) {
            int rows = size[0];
            int cols = size[1];
            HeightField h = NaiveDft.randomPatch(rows, cols, 0.5, 0.1, 77L + rows);
            int highestOrder = 6;
            Path ours = tmp.resolve("ours" + rows);
            ThesisFormat.write(ours, TaylorTermComputer.compute(h, highestOrder, Reporter.SILENT),
                    new ThesisFormat.Provenance("h", null, null), Reporter.SILENT);
            Path octave = Files.createDirectories(tmp.resolve("octave" + rows));
            Path heights = tmp.resolve("heights" + rows + ".txt");
            StringBuilder text = new StringBuilder();
            for (int r = 0; r < rows; r++) {
                for (int c = 0; c < cols; c++) {
                    text.append(String.format(Locale.ROOT, "%.17g ", h.heightUm(r, c)));
                }
                text.append('\n');
            }
            Files.writeString(heights, text);
            runOctave(String.format(Locale.ROOT, "addpath('%s'); compute_fft_images('%s', %.17g, %d, '%s')",
                    Path.of("precompute").toAbsolutePath(), heights, h.pixelSizeXUm(), highestOrder, octave));
            List<ThesisExtrema.Term> oursExtrema = ThesisExtrema.read(ours.resolve(ThesisFormat.EXTREMA_FILE)).terms();
            ThesisExtrema.File octaveExtrema = ThesisExtrema.read(octave.resolve(ThesisFormat.EXTREMA_FILE));
            assertEquals(h.pixelSizeXUm() * 1e-6, octaveExtrema.pixelSizeMetres(), 1e-20);
            double worstValue = 0;
            for (int n = 0; n <= highestOrder; n++) {
                ThesisRecipe.TermFile o = ThesisRecipe.TermFile.read(octave.resolve(ThesisFormat.termFileName(n)));
                ThesisRecipe.TermFile w = ThesisRecipe.TermFile.read(ours.resolve(ThesisFormat.termFileName(n)));
                assertEquals(o.width(), w.width());
                assertEquals(o.height(), w.height());
                // the Octave file de-normalised with its own extrema is the reference image
                ThesisExtrema.Term oe = octaveExtrema.terms().get(n);
                double[][] reference = new double[2][rows * cols];
                for (int i = 0; i < rows; i++) {
                    for (int j = 0; j < cols; j++) {
                        reference[0][i * cols + j] = oe.re().denormalise(o.at(i, j, 0));
                        reference[1][i * cols + j] = oe.im().denormalise(o.at(i, j, 1));
                        assertEquals(0.5f, o.at(i, j, 2));
                    }
                }
                worstValue = Math.max(worstValue, compare(reference, w, oursExtrema.get(n), rows, cols,
                        "octave term " + n));
            }
            TestReport.printf(ThesisRecipeTest.class, Locale.ROOT, "thesis recipe (Octave) %dx%d: worst |difference| = %.3f ulp(1f) x "
                    + "(scale + range)%n", rows, cols, worstValue);
        }
    }

    /**
     * Compares our file, de-normalised with our extrema, to a reference image (double, row 0 at the top).
     * Where the Re channel is well conditioned (range above 1e-6 of the scale) the stored normalised floats are
     * checked directly too. Returns the worst difference in units of ulp(1f) (scale + range).
     */
    private static double compare(double[][] reference, ThesisRecipe.TermFile ours, ThesisExtrema.Term extrema,
                                  int rows, int cols, String what) {
        double scale = 0;
        for (double[] channel : reference) {
            for (double v : channel) {
                scale = Math.max(scale, Math.abs(v));
            }
        }
        double worst = 0;
        ThesisExtrema.Channel[] channels = {extrema.re(), extrema.im()};
        for (int k = 0; k < 2; k++) {
            ThesisExtrema.Channel ch = channels[k];
            double unit = ThesisFormatTest.ULP_OF_ONE * (scale + ch.range());
            for (int i = 0; i < rows; i++) {
                for (int j = 0; j < cols; j++) {
                    double want = reference[k][i * cols + j];
                    double have = ch.denormalise(ours.at(i, j, k));
                    double difference = Math.abs(have - want);
                    assertTrue(difference <= 2 * unit, String.format(Locale.ROOT,
                            "%s %s at script row %d col %d: %g vs %g (difference %.3g, allowed %.3g)", what,
                            k == 0 ? "Re" : "Im", i, j, have, want, difference, 2 * unit));
                    worst = Math.max(worst, difference / unit);
                    if (ch.range() > 1e-6 * scale) {
                        double normalised = (want - ch.min()) / ch.range();
                        assertEquals(normalised, ours.at(i, j, k), 2 * unit / ch.range(), what + " normalised");
                    }
                }
            }
        }
        return worst;
    }

    private static boolean octaveOnPath() {
        try {
            Process p = new ProcessBuilder("octave", "--version").redirectErrorStream(true).start();
            p.getInputStream().readAllBytes();
            return p.waitFor(30, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    private static void runOctave(String code) throws IOException, InterruptedException {
        Process p = new ProcessBuilder("octave", "--no-gui", "--norc", "--quiet", "--no-window-system", "--eval", code)
                .redirectErrorStream(true).start();
        String output = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "octave did not finish: " + output);
        assertEquals(0, p.exitValue(), "octave failed: " + output);
    }
}
