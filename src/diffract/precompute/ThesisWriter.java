package diffract.precompute;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import diffract.optics.settings.SpectralSettings;
import diffract.optics.spectra.TaylorTerms;
import diffract.util.ImageFiles;
import diffract.util.Reporter;
import diffract.util.Version;

import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** Writes a {@link ThesisFormat} folder from our terms (see there for the layout). */
final class ThesisWriter {
    /** The thesis' wavelength step (001 implementation notes), written to paramters.txt for information. */
    static final int LAMBDA_STEP_NM = 5;
    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private ThesisWriter() {
    }

    static void write(Path dir, TaylorTerms terms, ThesisFormat.Provenance provenance, Reporter reporter)
            throws IOException {
        // Pixel sizes read from different headers (or computed as width / columns) differ in their last bits
        // when they are equal: only a real difference is worth a warning.
        if (Math.abs(terms.pixelSizeXUm() - terms.pixelSizeYUm())
                > 1e-9 * Math.max(terms.pixelSizeXUm(), terms.pixelSizeYUm())) {
            reporter.warn(String.format(Locale.ROOT, "the thesis format has one pixel size dH; extrema.txt gets x's "
                    + "%.6g um (y is %.6g um, kept in %s only)", terms.pixelSizeXUm(), terms.pixelSizeYUm(),
                    ThesisFormat.EXTRAS_FILE));
        }
        Files.createDirectories(dir);
        // extrema.txt marks a folder as complete (it is written last): while we overwrite, the folder reads as
        // incomplete rather than as a mix of old and new terms.
        Files.deleteIfExists(dir.resolve(ThesisFormat.EXTREMA_FILE));
        Files.deleteIfExists(dir.resolve(ThesisFormat.EXTRAS_FILE));
        int rows = terms.rows();
        int cols = terms.cols();
        List<ThesisExtrema.Term> extrema = new ArrayList<>();
        List<ThesisExtras.TermExtrema> exact = new ArrayList<>();
        for (int n = 0; n < terms.termCount(); n++) {
            double[] image = ThesisLayout.toThesis(terms.termData(n), rows, cols);
            ThesisExtrema.Term term = new ThesisExtrema.Term(ThesisExtrema.Channel.of(image, 0),
                    ThesisExtrema.Channel.of(image, 1));
            extrema.add(term);
            exact.add(new ThesisExtras.TermExtrema(n, term.re().min(), term.re().range(), term.im().min(),
                    term.im().range()));
            writeTerm(dir.resolve(ThesisFormat.termFileName(n)), image, term, rows, cols);
        }
        String source = provenance.source() != null ? provenance.source() : "unknown";
        ImageFiles.writeAtomically(dir.resolve(ThesisFormat.PARAMETERS_FILE),
                out -> out.write(parameters(terms, source).getBytes(StandardCharsets.US_ASCII)));
        ThesisExtras extras = new ThesisExtras(ThesisExtras.FORMAT, ThesisExtras.FORMAT_VERSION, Version.VERSION,
                ThesisExtras.MICROMETRES, source, provenance.patchSha256(), rows, cols, terms.pixelSizeXUm(),
                terms.pixelSizeYUm(), provenance.maxHeightUm(), terms.maxAbsHeightUm(), terms.highestOrder(), exact);
        byte[] json = JSON.writeValueAsBytes(extras);
        ImageFiles.writeAtomically(dir.resolve(ThesisFormat.EXTRAS_FILE), out -> out.write(json));
        double pixelSizeMetres = terms.pixelSizeXUm() * 1e-6;
        ImageFiles.writeAtomically(dir.resolve(ThesisFormat.EXTREMA_FILE),
                out -> out.write(ThesisExtrema.text(extrema, pixelSizeMetres).getBytes(StandardCharsets.US_ASCII)));
        // terms beyond N left by an earlier, longer run would confuse someone listing the folder
        for (int n = terms.termCount(); Files.deleteIfExists(dir.resolve(ThesisFormat.termFileName(n))); n++) {
            // deleted
        }
    }

    /**
     * {@code AmpReIm<n>.txt}: big-endian int32 width (cols) and height (rows), then per texel row from the bottom
     * of the script's image to its top, per column from the left, the float32 triple (Re norm., Im norm., 0.5).
     */
    private static void writeTerm(Path file, double[] image, ThesisExtrema.Term term, int rows, int cols)
            throws IOException {
        ImageFiles.writeAtomically(file, raw -> {
            DataOutputStream out = new DataOutputStream(raw); // big-endian, as Octave's 'ieee-be'
            out.writeInt(cols);
            out.writeInt(rows);
            ByteBuffer row = ByteBuffer.allocate(12 * cols).order(ByteOrder.BIG_ENDIAN);
            for (int fileRow = 0; fileRow < rows; fileRow++) {
                int i = ThesisLayout.thesisRowOfFileRow(fileRow, rows);
                row.clear();
                for (int j = 0; j < cols; j++) {
                    int p = 2 * (i * cols + j);
                    row.putFloat(term.re().normalise(image[p]));
                    row.putFloat(term.im().normalise(image[p + 1]));
                    row.putFloat(0.5f);
                }
                out.write(row.array());
            }
            out.flush();
        });
    }

    /**
     * paramters.txt (sic, the script's name): one integer per line, then the input path. Informative only: no
     * reader relies on it (the term count comes from extrema.txt).
     * <ol>
     *   <li>lambda min, nm (380, the range every variant integrates over)</li>
     *   <li>lambda max, nm (780)</li>
     *   <li>termCnt, the script's loop bound {@code for t = 0:termCnt}: the highest order N, files AmpReIm0..N</li>
     *   <li>N, the patch width in pixels (the thesis' "N x N pixel image"; columns)</li>
     *   <li>the patch height in pixels (rows)</li>
     *   <li>the wavelength step, nm (5, the thesis' FLSS step)</li>
     *   <li>the pixel size dH (x), nm, rounded to an integer</li>
     *   <li>the input path</li>
     * </ol>
     */
    static String parameters(TaylorTerms terms, String source) {
        long[] numbers = {Math.round(SpectralSettings.LAMBDA_MIN_NM), Math.round(SpectralSettings.LAMBDA_MAX_NM),
                terms.highestOrder(), terms.cols(), terms.rows(), LAMBDA_STEP_NM,
                Math.round(terms.pixelSizeXUm() * 1e3)};
        StringBuilder out = new StringBuilder();
        for (long v : numbers) {
            out.append(v).append('\n');
        }
        return out.append(source.replace('\n', ' ')).append('\n').toString();
    }
}
