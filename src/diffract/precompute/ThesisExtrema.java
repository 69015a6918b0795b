package diffract.precompute;

import diffract.util.UserInputException;

import java.io.IOException;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The thesis' normalisation (003 eq. 1.1) and its {@code extrema.txt}: per term, Re and Im are mapped to [0, 1]
 * separately, v = (x - min) / range, and the file holds 8 lines per term, each printed like C's {@code %36.35f}:
 * <pre>
 *   minRe, minIm, 0, dH, rangeRe, rangeIm, 1, dH      (dH: the pixel size in metres)
 * </pre>
 * The script's guards are kept: a min with |min| < 1e-35 is stored as 0, the range is max - (that min), and a
 * range below 1e-35 is stored as 1, because 35 decimals cannot print anything smaller; such a channel is then
 * stored un-normalised (v = x).
 */
public final class ThesisExtrema {
    /** Below this, 35 fixed-point decimals print zero: the script's guard for mins and ranges. */
    public static final double GUARD = 1e-35;
    static final int LINES_PER_TERM = 8;

    private ThesisExtrema() {
    }

    /** One channel's eq. 1.1 mapping, guards applied. */
    public record Channel(double min, double range) {
        /** The guarded extrema of every second value of {@code image}, starting at {@code offset} (0 Re, 1 Im). */
        public static Channel of(double[] image, int offset) {
            double min = Double.POSITIVE_INFINITY;
            double max = Double.NEGATIVE_INFINITY;
            for (int i = offset; i < image.length; i += 2) {
                min = Math.min(min, image[i]);
                max = Math.max(max, image[i]);
            }
            return ofExtrema(min, max);
        }

        /** The guarded mapping of a channel whose values span [min, max]. */
        public static Channel ofExtrema(double min, double max) {
            double guardedMin = Math.abs(min) < GUARD ? 0.0 : min;
            double range = max - guardedMin;
            return new Channel(guardedMin, range < GUARD ? 1.0 : range);
        }

        /** (x - min) / range in double, rounded once to the stored float32. */
        public float normalise(double x) {
            return (float) ((x - min) / range);
        }

        /** The inverse, min + v range, in double. */
        public double denormalise(float v) {
            return min + v * range;
        }
    }

    /** Term n's two channels. */
    public record Term(Channel re, Channel im) {
    }

    /** The content of an {@code extrema.txt}: the terms' channels and the pixel size dH as written, in metres. */
    public record File(List<Term> terms, double pixelSizeMetres) {
    }

    /** C's {@code %36.35f}: the exact binary value rounded half-even to 35 decimals, padded left to 36 characters. */
    public static String format(double value) {
        String text = new BigDecimal(value).setScale(35, RoundingMode.HALF_EVEN).toPlainString();
        return text.length() >= 36 ? text : " ".repeat(36 - text.length()) + text;
    }

    /** The file's text, one line per value, '\n' line ends. */
    public static String text(List<Term> terms, double pixelSizeMetres) {
        StringBuilder out = new StringBuilder();
        for (Term t : terms) {
            double[] lines = {t.re().min(), t.im().min(), 0, pixelSizeMetres,
                    t.re().range(), t.im().range(), 1, pixelSizeMetres};
            for (double v : lines) {
                out.append(format(v)).append('\n');
            }
        }
        return out.toString();
    }

    /** Parses {@code file}; every failure is a one-line {@link UserInputException} naming the file and line. */
    public static File read(Path file) {
        List<String> lines;
        try {
            lines = Files.readAllLines(file, StandardCharsets.US_ASCII);
        } catch (NoSuchFileException e) {
            throw new UserInputException("missing " + file + ": a thesis term folder needs its extrema.txt", e);
        } catch (IOException e) {
            throw new UserInputException("cannot read " + file + ": " + e.getMessage(), e);
        }
        List<double[]> values = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i).trim();
            if (line.isEmpty()) {
                continue; // a trailing blank line is harmless
            }
            try {
                double v = Double.parseDouble(line);
                if (!Double.isFinite(v)) {
                    throw new NumberFormatException("not finite");
                }
                values.add(new double[] {v, i + 1});
            } catch (NumberFormatException e) {
                throw new UserInputException(file + " line " + (i + 1) + ": '" + line + "' is not a number", e);
            }
        }
        if (values.isEmpty() || values.size() % LINES_PER_TERM != 0) {
            throw new UserInputException(file + " has " + values.size() + " numbers; expected 8 per term "
                    + "(minRe, minIm, 0, dH, rangeRe, rangeIm, 1, dH)");
        }
        List<Term> terms = new ArrayList<>();
        double dH = values.get(3)[0];
        for (int t = 0; t < values.size() / LINES_PER_TERM; t++) {
            int b = t * LINES_PER_TERM;
            for (int k : new int[] {3, 7}) {
                double[] v = values.get(b + k);
                if (Math.abs(v[0] - dH) > 1e-9 * Math.abs(dH)) {
                    throw new UserInputException(file + " line " + (int) v[1] + ": dH " + v[0] + " differs from "
                            + dH + " of term 0; every term must share one pixel size");
                }
            }
            double rangeRe = values.get(b + 4)[0];
            double rangeIm = values.get(b + 5)[0];
            if (!(rangeRe > 0) || !(rangeIm > 0)) {
                throw new UserInputException(file + " line " + (int) values.get(b + (rangeRe > 0 ? 5 : 4))[1]
                        + ": term " + t + " has a range <= 0; ranges are max - min (1 when the term is flat)");
            }
            terms.add(new Term(new Channel(values.get(b)[0], rangeRe), new Channel(values.get(b + 1)[0], rangeIm)));
        }
        return new File(terms, dH);
    }
}
