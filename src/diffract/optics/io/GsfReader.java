package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;
import diffract.util.Reporter;
import diffract.util.UserInputException;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.OptionalDouble;

import static diffract.optics.io.ReaderSupport.printable;

/**
 * Gwyddion Simple Field (.gsf, http://gwyddion.net/documentation/user-guide-en/gsf.html): the magic line
 * {@code Gwyddion Simple Field 1.0}, {@code Key = Value} header lines, 1 to 4 NUL bytes that pad the header to a
 * multiple of 4, then XRes * YRes little-endian float32 values, row by row from the top. Physical sizes
 * (XReal, YReal) and heights are in metres unless XYUnits / ZUnits say otherwise; the field is in micrometres.
 */
final class GsfReader {
    static final String MAGIC_PREFIX = "Gwyddion Simple Field";
    private static final String MAGIC_LINE = MAGIC_PREFIX + " 1.0";

    private GsfReader() {
    }

    static boolean looksLikeGsf(byte[] bytes) {
        byte[] magic = MAGIC_PREFIX.getBytes(StandardCharsets.US_ASCII);
        if (bytes.length < magic.length) {
            return false;
        }
        for (int i = 0; i < magic.length; i++) {
            if (bytes[i] != magic[i]) {
                return false;
            }
        }
        return true;
    }

    /**
     * @param pixelSizeUm the user's --pixel-size, or null to use XReal/XRes and YReal/YRes from the header
     */
    static HeightField read(Path file, byte[] bytes, Double pixelSizeUm, Reporter reporter) {
        int headerEnd = indexOfNul(bytes);
        String header = new String(bytes, 0, headerEnd < 0 ? bytes.length : headerEnd, StandardCharsets.UTF_8);
        String[] lines = header.split("\r?\n", -1);
        if (!looksLikeGsf(bytes)) {
            throw new UserInputException(file + ": not a Gwyddion Simple Field (the first line must be '" + MAGIC_LINE
                    + "'); export the data from Gwyddion as .gsf again");
        }
        if (!lines[0].strip().equals(MAGIC_LINE)) {
            throw new UserInputException(file + ": unsupported GSF version '" + printable(lines[0].strip())
                    + "'; only '" + MAGIC_LINE + "' is known");
        }
        if (headerEnd < 0) {
            throw new UserInputException(file + ": the GSF header is not terminated by NUL bytes; the file is"
                    + " truncated or damaged, export it again");
        }
        Map<String, String> fields = parseHeader(file, lines);

        int xRes = resolution(file, fields, "XRes");
        int yRes = resolution(file, fields, "YRes");
        if ((long) xRes * yRes > Integer.MAX_VALUE / 4 - 8) {
            throw new UserInputException(file + ": XRes x YRes = " + xRes + " x " + yRes
                    + " is too large; crop the data to the patch you need");
        }

        // The header plus its 1..4 NUL bytes fill a multiple of 4, so the data starts here.
        int dataStart = headerEnd + (4 - headerEnd % 4);
        long expectedBytes = 4L * xRes * yRes;
        long actualBytes = Math.max(0, bytes.length - dataStart);
        if (actualBytes < expectedBytes) {
            throw new UserInputException(file + ": truncated GSF: XRes x YRes = " + xRes + " x " + yRes
                    + " needs " + expectedBytes + " bytes of float32 data after the header, found " + actualBytes
                    + "; copy or export the file again");
        }
        for (int i = headerEnd; i < dataStart; i++) {
            if (bytes[i] != 0) {
                throw new UserInputException(file + ": the GSF header padding is wrong (the header must end with"
                        + " NUL bytes up to a multiple of 4 bytes); the file is damaged, export it again");
            }
        }
        if (actualBytes > expectedBytes) {
            reporter.warn(file + ": ignoring " + (actualBytes - expectedBytes) + " bytes after the "
                    + xRes + " x " + yRes + " float32 samples");
        }

        double zToUm = unitToUm(file, fields, "ZUnits", "heights");
        double xyToUm = unitToUm(file, fields, "XYUnits", "XReal and YReal");
        double[] pixel = pixelSizesUm(file, fields, xRes, yRes, xyToUm, pixelSizeUm, reporter);

        ByteBuffer data = ByteBuffer.wrap(bytes, dataStart, (int) expectedBytes).order(ByteOrder.LITTLE_ENDIAN);
        double[] heightsUm = new double[xRes * yRes];
        int nonFinite = 0;
        int firstBad = -1;
        for (int i = 0; i < heightsUm.length; i++) {
            float value = data.getFloat();
            if (!Float.isFinite(value)) {
                if (nonFinite++ == 0) {
                    firstBad = i;
                }
            }
            heightsUm[i] = value * zToUm;
        }
        if (nonFinite > 0) {
            throw ReaderSupport.nonFinite(file, nonFinite, firstBad / xRes, firstBad % xRes, heightsUm[firstBad]);
        }
        return ReaderSupport.build(file, yRes, xRes, heightsUm, pixel[0], pixel[1]);
    }

    private static Map<String, String> parseHeader(Path file, String[] lines) {
        Map<String, String> fields = new HashMap<>();
        for (int i = 1; i < lines.length; i++) {
            String line = lines[i].strip();
            if (line.isEmpty()) {
                continue;
            }
            int equals = line.indexOf('=');
            if (equals <= 0) {
                throw new UserInputException(file + ": GSF header line " + (i + 1) + " ('" + printable(line)
                        + "') is not of the form 'Key = Value'; the file is damaged, export it again");
            }
            fields.put(line.substring(0, equals).strip(), line.substring(equals + 1).strip());
        }
        return fields;
    }

    private static int resolution(Path file, Map<String, String> fields, String key) {
        String value = fields.get(key);
        if (value == null) {
            throw new UserInputException(file + ": the GSF header lacks the mandatory " + key
                    + "; export the file from Gwyddion again");
        }
        int res;
        try {
            res = Integer.parseInt(value);
        } catch (NumberFormatException e) {
            throw new UserInputException(file + ": GSF " + key + " = '" + printable(value)
                    + "' is not a whole number of samples", e);
        }
        if (res <= 0) {
            throw new UserInputException(file + ": GSF " + key + " = " + res + ": the file has zero samples;"
                    + " export a non-empty height map");
        }
        return res;
    }

    /** Gwyddion writes base SI units ("m"); prefixed lengths are accepted for hand-written files. */
    private static double unitToUm(Path file, Map<String, String> fields, String key, String what) {
        String unit = fields.get(key);
        if (unit == null || unit.isEmpty()) {
            return 1e6; // metres, the GSF convention
        }
        OptionalDouble factor = LengthUnit.micrometres(unit);
        if (factor.isEmpty()) {
            throw new UserInputException(file + ": GSF " + key + " = '" + printable(unit) + "' is not a length"
                    + " unit for the " + what + " (supported: " + LengthUnit.KNOWN + "); a height map is needed,"
                    + " not another channel");
        }
        return factor.getAsDouble();
    }

    /** {x, y} pixel sizes in micrometres. */
    private static double[] pixelSizesUm(Path file, Map<String, String> fields, int xRes, int yRes, double xyToUm,
                                         Double pixelSizeUm, Reporter reporter) {
        Double xRealUm = physicalSizeUm(file, fields, "XReal", xyToUm);
        Double yRealUm = physicalSizeUm(file, fields, "YReal", xyToUm);
        if (pixelSizeUm != null) {
            if (xRealUm != null || yRealUm != null) {
                String fromFile = xRealUm != null && yRealUm != null
                        ? ReaderSupport.num(xRealUm / xRes) + " x " + ReaderSupport.num(yRealUm / yRes) + " um"
                        : ReaderSupport.num((xRealUm != null ? xRealUm / xRes : yRealUm / yRes)) + " um";
                reporter.info(file + ": the given pixel size " + ReaderSupport.num(pixelSizeUm)
                        + " um overrides the file's pixel size of " + fromFile + " (XReal/XRes, YReal/YRes)");
            }
            return new double[] {pixelSizeUm, pixelSizeUm};
        }
        if (xRealUm == null && yRealUm == null) {
            throw new InvalidSettingException(Quantity.PIXEL_SIZE, file + ": the GSF header has no XReal/YReal, so"
                    + " the pixel size is unknown; give the pixel size in micrometres");
        }
        if (xRealUm == null || yRealUm == null) {
            // The spec's default for a missing size is 1 (metre), never what a measurement meant; square
            // pixels are the likely intent.
            double side = xRealUm != null ? xRealUm / xRes : yRealUm / yRes;
            reporter.info(file + ": the GSF header gives only " + (xRealUm != null ? "XReal" : "YReal")
                    + "; assuming square pixels of " + ReaderSupport.num(side) + " um");
            return new double[] {side, side};
        }
        return new double[] {xRealUm / xRes, yRealUm / yRes};
    }

    private static Double physicalSizeUm(Path file, Map<String, String> fields, String key, double xyToUm) {
        String value = fields.get(key);
        if (value == null) {
            return null;
        }
        double real;
        try {
            real = Double.parseDouble(value);
        } catch (NumberFormatException e) {
            throw new UserInputException(file + ": GSF " + key + " = '" + printable(value) + "' is not a number", e);
        }
        if (!(real > 0) || !Double.isFinite(real)) {
            throw new InvalidSettingException(Quantity.PIXEL_SIZE, file + ": GSF " + key + " = " + value
                    + " must be a positive physical size (in metres); fix the header or give the pixel size");
        }
        return real * xyToUm;
    }

    private static int indexOfNul(byte[] bytes) {
        for (int i = 0; i < bytes.length; i++) {
            if (bytes[i] == 0) {
                return i;
            }
        }
        return -1;
    }
}
