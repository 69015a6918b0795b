package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.util.MemoryEstimate;
import diffract.util.Reporter;
import diffract.util.UserInputException;

import java.math.BigDecimal;
import java.math.MathContext;
import java.nio.file.Path;

/** Helpers shared by the per-format readers: number formatting, unit guesses, building a field. */
final class ReaderSupport {
    private ReaderSupport() {
    }

    /** Up to 4 significant digits, no exponent, no trailing zeros: "0.0686", "68.6", "380". */
    static String num(double value) {
        if (!Double.isFinite(value)) {
            return Double.toString(value);
        }
        if (value == 0) {
            return "0";
        }
        return new BigDecimal(value).round(new MathContext(4)).stripTrailingZeros().toPlainString();
    }

    /** A value from a file, fit for a one-line message: at most 40 characters, control characters as '?'. */
    static String printable(String s) {
        String clipped = s.length() > 40 ? s.substring(0, 40) + "..." : s;
        return clipped.replaceAll("\\p{Cntrl}", "?");
    }

    /**
     * Wraps {@link HeightField#of} so that its (file-agnostic) complaints name the file: the readers check
     * non-finite values themselves, so this is the last line of defence.
     */
    static HeightField build(Path file, int rows, int cols, double[] heightsUm, double pixelSizeXUm,
                             double pixelSizeYUm) {
        try {
            return HeightField.of(rows, cols, heightsUm, pixelSizeXUm, pixelSizeYUm);
        } catch (UserInputException e) {
            throw new UserInputException(file + ": " + e.getMessage(), e);
        }
    }

    /**
     * Warns when a length in micrometres lies outside [lowUm, highUm]. A value off by exactly a unit prefix is
     * the usual mistake (nanometres or metres typed where micrometres were meant), so we name the likely unit
     * and the value it would have been.
     *
     * @param what   e.g. "pixel size", "maximum height"
     * @param unitOf e.g. "per pixel" or "" (appears after "um")
     * @param source where the value came from, e.g. "the given pixel size" or "XReal/XRes in the header"
     */
    static void warnIfImplausible(Path file, String what, double valueUm, String unitOf, double lowUm,
                                  double highUm, String source, Reporter reporter) {
        if (valueUm >= lowUm && valueUm <= highUm) {
            return;
        }
        String shown = num(valueUm) + " um" + (unitOf.isEmpty() ? "" : " " + unitOf);
        // Candidate misreadings, most common first: value given in nm, in m, in mm.
        String[] names = {"nanometres", "metres", "millimetres"};
        double[] factors = {1e-3, 1e6, 1e3};
        for (int i = 0; i < names.length; i++) {
            double guess = valueUm * factors[i];
            if (guess >= lowUm && guess <= highUm) {
                reporter.warn(file + ": the " + what + " looks like " + names[i] + ": " + shown + " (from " + source
                        + "); did you mean " + num(guess) + "? Plausible values are " + num(lowUm) + " to "
                        + num(highUm) + " um");
                return;
            }
        }
        reporter.warn(file + ": the " + what + " of " + shown + " (from " + source + ") is outside the plausible range "
                + num(lowUm) + " to " + num(highUm) + " um for a nanostructure; check its unit");
    }

    /** The fix for missing samples, in the menus of the program that most AFM users have. */
    static final String FILL_MISSING = "fill them in Gwyddion (Data Process > Correct Data > Remove Data Under Mask)"
            + " or crop them";

    /** Thrown for missing samples: AFM software marks them with NaN, so say how many and where the first is. */
    static UserInputException nonFinite(Path file, int count, int firstRow, int firstCol, double firstValue) {
        String where = "row " + firstRow + ", column " + firstCol + " (counting from 0)";
        return new UserInputException(file + ": " + (count == 1
                ? "1 sample is NaN or infinite (missing data), at " + where + ": " + firstValue
                : count + " samples are NaN or infinite (missing data), the first at " + where + ": " + firstValue)
                + "; " + FILL_MISSING);
    }

    /**
     * Bytes of the heap a channel of {@code samples} values takes on its way to a levelled height field: its values
     * as read, the heights in micrometres, the field's own copy and the levelled copy, 8 bytes each.
     */
    static final long HEAP_BYTES_PER_SAMPLE = 32;

    /**
     * Refuses a header's image size before anything is allocated: a size that is not positive, more samples than
     * the file holds (at {@code sampleBytes} each) or than one Java array takes, or more than the heap can hold.
     *
     * @param what the channel or image in messages
     */
    static void requireSize(Path file, long cols, long rows, long sampleBytes, long fileBytes, String what) {
        if (cols <= 0 || rows <= 0) {
            throw new UserInputException(file + ": " + what + " is " + cols + " x " + rows + " samples, not an image;"
                    + " the file is damaged, save it again");
        }
        if (cols > Integer.MAX_VALUE || rows > Integer.MAX_VALUE || cols * rows > Integer.MAX_VALUE - 8) {
            throw new UserInputException(file + ": " + what + " claims " + cols + " x " + rows + " samples, more than"
                    + " one array holds; crop the scan");
        }
        long samples = cols * rows;
        if (sampleBytes > 0 && samples * sampleBytes > fileBytes) {
            throw new UserInputException(file + ": " + what + " claims " + cols + " x " + rows + " samples of "
                    + sampleBytes + " bytes (" + samples * sampleBytes + " bytes), more than the file's " + fileBytes
                    + "; the file is truncated or damaged, copy or save it again");
        }
        requireHeap(file, samples, what);
    }

    /** Refuses {@code samples} values that the heap cannot take ({@link #HEAP_BYTES_PER_SAMPLE} each). */
    static void requireHeap(Path file, long samples, String what) {
        MemoryEstimate.of("its samples", HEAP_BYTES_PER_SAMPLE * samples).require(file + ": " + what + " of "
                + samples + " samples", "crop the scan");
    }

    /** Row-major values with their rows in reverse order (a file that stores the bottom row first). */
    static double[] flippedRows(double[] values, int cols, int rows) {
        double[] out = new double[values.length];
        for (int r = 0; r < rows; r++) {
            System.arraycopy(values, (rows - 1 - r) * cols, out, r * cols, cols);
        }
        return out;
    }
}
