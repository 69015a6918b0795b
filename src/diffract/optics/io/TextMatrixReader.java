package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.util.UserInputException;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.regex.Pattern;

/**
 * Plain-text height matrices (.txt, .csv, .asc, .dat, e.g. Gwyddion's "ASCII data matrix" export): one row of
 * heights in micrometres per line, separated by whitespace, commas or semicolons; text after {@code #} and
 * blank lines are ignored. The first data line is row 0.
 */
final class TextMatrixReader {
    private static final Pattern SEPARATORS = Pattern.compile("[\\s,;]+");
    // Plain decimal numbers only: Double.parseDouble would also accept "1d", "0x1p3" or "Infinity",
    // which in a height file are typos, not heights.
    private static final Pattern NUMBER = Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?");
    private static final Pattern NOT_FINITE = Pattern.compile("[+-]?(nan|inf|infinity)");

    private TextMatrixReader() {
    }

    /**
     * Whether the bytes read as a text matrix: no NUL or other binary byte in the first 4 kB, and the first line
     * that is neither blank nor a comment starts with a plain decimal number.
     */
    static boolean looksLikeText(byte[] bytes) {
        int n = Math.min(bytes.length, 4096);
        for (int i = 0; i < n; i++) {
            int c = bytes[i] & 0xFF;
            if (c < 0x09 || c > 0x0D && c < 0x20) {
                return false;
            }
        }
        String head = new String(bytes, 0, n, StandardCharsets.UTF_8);
        if (head.startsWith("\uFEFF")) {
            head = head.substring(1);
        }
        for (String line : head.split("\r\n|\r|\n")) {
            int hash = line.indexOf('#');
            String data = (hash >= 0 ? line.substring(0, hash) : line).strip();
            if (!data.isEmpty()) {
                String[] tokens = SEPARATORS.split(data);
                return tokens.length > 0 && NUMBER.matcher(tokens[0]).matches();
            }
        }
        return false;
    }

    static HeightField read(Path file, byte[] bytes, double pixelSizeUm) {
        String text = new String(bytes, StandardCharsets.UTF_8);
        if (text.startsWith("\uFEFF")) {
            text = text.substring(1); // byte-order mark written by some Windows editors
        }
        String[] lines = text.split("\r\n|\r|\n", -1);
        DoubleList values = new DoubleList();
        int cols = -1;
        int firstDataLine = -1;
        int rows = 0;
        int nonFiniteCount = 0;
        int firstBadRow = -1;
        int firstBadCol = -1;
        double firstBadValue = 0;
        for (int lineIndex = 0; lineIndex < lines.length; lineIndex++) {
            String line = lines[lineIndex];
            int hash = line.indexOf('#');
            if (hash >= 0) {
                line = line.substring(0, hash);
            }
            line = line.strip();
            if (line.isEmpty()) {
                continue;
            }
            int lineNumber = lineIndex + 1;
            String[] tokens = SEPARATORS.split(line);
            int start = tokens.length > 0 && tokens[0].isEmpty() ? 1 : 0; // a line starting with a separator
            int count = tokens.length - start;
            if (cols < 0) {
                cols = count;
                firstDataLine = lineNumber;
            } else if (count != cols) {
                throw new UserInputException(file + ": line " + lineNumber + " has " + count + " values but line "
                        + firstDataLine + " (the first data line) has " + cols
                        + "; every row of the matrix must have the same length");
            }
            for (int t = start; t < tokens.length; t++) {
                double value = parse(file, tokens[t], lineNumber);
                if (!Double.isFinite(value)) {
                    if (nonFiniteCount++ == 0) {
                        firstBadRow = rows;
                        firstBadCol = t - start;
                        firstBadValue = value;
                    }
                }
                values.add(value);
            }
            rows++;
        }
        if (rows == 0) {
            throw new UserInputException(file + ": the text file contains no numbers (only blank or # comment lines);"
                    + " expected one row of heights in micrometres per line");
        }
        if (nonFiniteCount > 0) {
            throw ReaderSupport.nonFinite(file, nonFiniteCount, firstBadRow, firstBadCol, firstBadValue);
        }
        return ReaderSupport.build(file, rows, cols, values.toArray(), pixelSizeUm, pixelSizeUm);
    }

    private static double parse(Path file, String token, int lineNumber) {
        if (NUMBER.matcher(token).matches()) {
            return Double.parseDouble(token);
        }
        String lower = token.toLowerCase(Locale.ROOT);
        if (NOT_FINITE.matcher(lower).matches()) {
            return lower.contains("nan") ? Double.NaN
                    : lower.startsWith("-") ? Double.NEGATIVE_INFINITY : Double.POSITIVE_INFINITY;
        }
        String shown = (token.length() > 20 ? token.substring(0, 20) + "..." : token)
                .replaceAll("\\p{Cntrl}", "?"); // keep the message one printable line for binary junk
        throw new UserInputException(file + ": line " + lineNumber + ": '" + shown + "' is not a number;"
                + " expected heights in micrometres separated by spaces, commas or semicolons (# starts a comment)");
    }

    /** Growable double array: a matrix of a few million heights should not be boxed. */
    private static final class DoubleList {
        private double[] data = new double[1024];
        private int size;

        void add(double value) {
            if (size == data.length) {
                data = Arrays.copyOf(data, data.length * 2);
            }
            data[size++] = value;
        }

        double[] toArray() {
            return Arrays.copyOf(data, size);
        }
    }
}
