package diffract.precompute;

import com.fasterxml.jackson.databind.ObjectMapper;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;
import diffract.optics.spectra.TaylorTerms;
import diffract.util.Reporter;
import diffract.util.UserInputException;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** Reads a {@link ThesisFormat} folder into our terms (see there for the layout and the unit rules). */
final class ThesisReader {
    /**
     * RMS heights (file units) at or below this are taken as metres: 2e-6 is 2 um RMS if metres, but 2 pm if
     * micrometres, which no measured nanostructure has.
     */
    static final double METRES_AT_MOST = 2e-6;
    /** RMS heights at or above this are micrometres: 0.2 nm if micrometres, but 0.2 mm if metres. */
    static final double MICROMETRES_AT_LEAST = 2e-4;
    /** A pixel size in metres is far below a millimetre; a larger dH is not in metres. */
    static final double MAX_PIXEL_SIZE_METRES = 1e-3;
    private static final ObjectMapper JSON = new ObjectMapper();

    private final Path dir;
    private final Reporter reporter;
    private int rows = -1;
    private int cols = -1;
    private int termCount;

    private ThesisReader(Path dir, Reporter reporter) {
        this.dir = dir;
        this.reporter = reporter;
    }

    static TaylorTerms read(Path dir, ThesisFormat.HeightUnit unit, Reporter reporter) {
        return new ThesisReader(dir, reporter).read(unit);
    }

    private TaylorTerms read(ThesisFormat.HeightUnit requested) {
        Path extremaFile = dir.resolve(ThesisFormat.EXTREMA_FILE);
        ThesisExtrema.File text = ThesisExtrema.read(extremaFile);
        ThesisExtras extras = readExtras(dir);
        int count = text.terms().size();
        termCount = count;
        List<ThesisExtrema.Term> channels = text.terms();
        if (extras != null) {
            channels = exactChannels(extras, count);
        }
        // term 0 first: it fixes the size every other term must have
        double[] term0 = readImage(0, channels.get(0));
        ThesisFormat.HeightUnit unit;
        if (extras != null) {
            reporter.info(dir + ": heights taken as micrometres (its " + ThesisFormat.EXTRAS_FILE + " says so)");
            unit = ThesisFormat.HeightUnit.MICROMETRES;
        } else {
            unit = decideUnit(requested, count > 1 ? readImage(1, channels.get(1)) : null);
        }
        if (extras != null && (extras.rows() != rows || extras.cols() != cols)) {
            throw new UserInputException(dir.resolve(ThesisFormat.EXTRAS_FILE) + " describes " + extras.rows() + "x"
                    + extras.cols() + " texels but " + ThesisFormat.termFileName(0) + " holds " + rows + "x" + cols
                    + "; delete " + ThesisFormat.EXTRAS_FILE + " to read the folder as the script's output");
        }
        double pixelSizeXUm;
        double pixelSizeYUm;
        if (extras != null) {
            pixelSizeXUm = extras.pixelSizeXUm();
            pixelSizeYUm = extras.pixelSizeYUm();
        } else {
            double dH = text.pixelSizeMetres();
            if (!(dH > 0) || dH >= MAX_PIXEL_SIZE_METRES) {
                throw new UserInputException(extremaFile + ": dH = " + dH + " is not a pixel size in metres "
                        + "(0 < dH < 1e-3 expected)");
            }
            pixelSizeXUm = dH * 1e6;
            pixelSizeYUm = pixelSizeXUm;
        }
        float[][] terms = new float[count][];
        List<Integer> underflowed = new ArrayList<>();
        for (int n = 0; n < count; n++) {
            double[] image = n == 0 ? term0 : readImage(n, channels.get(n));
            boolean allZero = toMicrometres(image, n, unit);
            if (allZero && n > 0) {
                underflowed.add(n);
            }
            terms[n] = ThesisLayout.toNative(image, rows, cols);
        }
        if (!underflowed.isEmpty()) {
            reporter.warn(dir + ": terms " + underflowed + " are all zero"
                    + (unit == ThesisFormat.HeightUnit.METRES ? " (with heights in metres the higher terms underflow"
                    + " float32; the script's micrometre output keeps them)" : ""));
        }
        double maxAbsHeightUm = extras != null ? extras.maxAbsHeightUm()
                : MaxHeightEstimate.fromMoments(terms, rows, cols).reportTo(reporter, dir);
        return new TaylorTerms(rows, cols, pixelSizeXUm, pixelSizeYUm, maxAbsHeightUm, terms);
    }

    /** The diffract.json of {@code dir}, or null when there is none; one we cannot use is an error. */
    static ThesisExtras readExtras(Path dir) {
        Path file = dir.resolve(ThesisFormat.EXTRAS_FILE);
        if (!Files.isRegularFile(file)) {
            return null;
        }
        try {
            ThesisExtras extras = JSON.readValue(file.toFile(), ThesisExtras.class);
            if (!ThesisExtras.FORMAT.equals(extras.format()) || extras.formatVersion() > ThesisExtras.FORMAT_VERSION
                    || !ThesisExtras.MICROMETRES.equals(extras.heightUnit())) {
                throw new UserInputException(file + " is not a diffract " + ThesisExtras.FORMAT + " file version <= "
                        + ThesisExtras.FORMAT_VERSION + " in um; delete it to read the folder as the script's output");
            }
            return extras;
        } catch (IOException e) {
            throw new UserInputException("cannot read " + file + " (" + e.getMessage().lines().findFirst().orElse("")
                    + "); delete it to read the folder as the script's output", e);
        }
    }

    /** True when extrema.txt and every term file diffract.json promises exist with the right size (no parsing). */
    static boolean filesLookComplete(Path dir, ThesisExtras extras) {
        try {
            if (!Files.isRegularFile(dir.resolve(ThesisFormat.EXTREMA_FILE))) {
                return false;
            }
            long bytes = 8L + 12L * extras.rows() * extras.cols();
            for (int n = 0; n <= extras.highestOrder(); n++) {
                if (Files.size(dir.resolve(ThesisFormat.termFileName(n))) != bytes) {
                    return false;
                }
            }
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    private List<ThesisExtrema.Term> exactChannels(ThesisExtras extras, int count) {
        if (extras.extrema() == null || extras.extrema().size() != count || extras.highestOrder() + 1 != count) {
            throw new UserInputException(dir.resolve(ThesisFormat.EXTRAS_FILE) + " describes terms 0.."
                    + extras.highestOrder() + " but " + ThesisFormat.EXTREMA_FILE + " lists " + count
                    + "; delete " + ThesisFormat.EXTRAS_FILE + " to read the folder as the script's output");
        }
        List<ThesisExtrema.Term> out = new ArrayList<>();
        for (ThesisExtras.TermExtrema e : extras.extrema()) {
            out.add(new ThesisExtrema.Term(new ThesisExtrema.Channel(e.reMin(), e.reRange()),
                    new ThesisExtrema.Channel(e.imMin(), e.imRange())));
        }
        return out;
    }

    /** Term n de-normalised, in the file's height unit, as the script's image: R x C, row 0 at the top. */
    private double[] readImage(int n, ThesisExtrema.Term channels) {
        Path file = dir.resolve(ThesisFormat.termFileName(n));
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(file);
        } catch (NoSuchFileException e) {
            throw new UserInputException("missing " + file + ": " + ThesisFormat.EXTREMA_FILE + " lists " + termCount
                    + " terms, " + ThesisFormat.termFileName(0) + ".." + ThesisFormat.termFileName(termCount - 1), e);
        } catch (IOException e) {
            throw new UserInputException("cannot read " + file + ": " + e.getMessage(), e);
        }
        if (bytes.length < 8) {
            throw new UserInputException(file + " is truncated: " + bytes.length + " bytes, not even the 8-byte "
                    + "width/height header");
        }
        ByteBuffer in = ByteBuffer.wrap(bytes).order(ByteOrder.BIG_ENDIAN);
        int width = in.getInt();
        int height = in.getInt();
        if (width <= 0 || height <= 0 || (long) width * height > Integer.MAX_VALUE / 12) {
            throw new UserInputException(file + ": header says " + width + " x " + height
                    + " texels; not a big-endian AmpReIm term file");
        }
        if (rows >= 0 && (width != cols || height != rows)) {
            throw new UserInputException(file + " is " + width + " x " + height + " texels but "
                    + ThesisFormat.termFileName(0) + " is " + cols + " x " + rows + "; all terms must have one size");
        }
        long expected = 8L + 12L * width * height;
        if (bytes.length != expected) {
            throw new UserInputException(file + (bytes.length < expected ? " is truncated: " : " is too long: ")
                    + bytes.length + " bytes, a " + width + " x " + height + " term has " + expected);
        }
        cols = width;
        rows = height;
        double[] image = new double[2 * width * height];
        for (int fileRow = 0; fileRow < height; fileRow++) {
            int i = ThesisLayout.thesisRowOfFileRow(fileRow, height);
            for (int j = 0; j < width; j++) {
                int p = 2 * (i * width + j);
                image[p] = channels.re().denormalise(in.getFloat());
                image[p + 1] = channels.im().denormalise(in.getFloat());
                in.getFloat(); // the constant 0.5 of the blue channel
            }
        }
        return image;
    }

    private ThesisFormat.HeightUnit decideUnit(ThesisFormat.HeightUnit requested, double[] term1) {
        if (term1 == null) {
            reporter.info(dir + ": only term 0, which does not depend on the heights: no height unit needed");
            return ThesisFormat.HeightUnit.MICROMETRES;
        }
        // Parseval for Matlab's ifft2: sum over frequencies |ifft2(i h)|^2 = mean(h^2), so term 1 alone gives the
        // RMS height in the file's unit, whatever the patch size.
        double sum = 0;
        for (double v : term1) {
            sum += v * v;
        }
        double rms = Math.sqrt(sum);
        if (requested != ThesisFormat.HeightUnit.AUTO) {
            reporter.info(String.format(Locale.ROOT, "%s: heights taken as %s (as asked; RMS height %.4g %s)",
                    dir, requested.words(), rms, requested.symbol()));
            return requested;
        }
        if (rms <= METRES_AT_MOST) {
            reporter.info(String.format(Locale.ROOT, "%s: heights taken as metres (detected: RMS height %.4g from "
                    + "term 1 is %.4g um in metres, %.4g pm in micrometres)", dir, rms, rms * 1e6, rms * 1e6));
            return ThesisFormat.HeightUnit.METRES;
        }
        if (rms >= MICROMETRES_AT_LEAST) {
            reporter.info(String.format(Locale.ROOT, "%s: heights taken as micrometres (detected: RMS height %.4g "
                    + "from term 1 is %.4g um, %.4g mm in metres)", dir, rms, rms, rms * 1e3));
            return ThesisFormat.HeightUnit.MICROMETRES;
        }
        throw new InvalidSettingException(Quantity.TERMS_HEIGHT_UNIT, String.format(Locale.ROOT, "%s: cannot tell "
                + "the heights' unit (RMS height %.4g from term 1: %.4g um in metres, %.4g nm in micrometres); "
                + "give the height unit, m or um", dir, rms, rms * 1e6, rms * 1e3));
    }

    /** Scales term n from (file unit)^n to um^n in place; true when every value is zero. */
    private static boolean toMicrometres(double[] image, int n, ThesisFormat.HeightUnit unit) {
        double factor = unit == ThesisFormat.HeightUnit.METRES ? Math.pow(1e6, n) : 1.0;
        boolean allZero = true;
        for (int i = 0; i < image.length; i++) {
            if (image[i] != 0) {
                allZero = false;
                image[i] *= factor;
                if (!Double.isFinite(image[i])) {
                    throw new InvalidSettingException(Quantity.TERMS_HEIGHT_UNIT, "term " + n
                            + " overflows in micrometres^" + n + "; read fewer terms or give the height unit um");
                }
            }
        }
        return allZero;
    }
}
