package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.util.Reporter;
import diffract.util.UserInputException;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.OptionalDouble;

/**
 * Igor binary waves (.ibw) of version 5, as Asylum Research AFMs save their images (WaveMetrics' Technical Note
 * PTN003, "Igor Binary Format"). A 64-byte BinHeader5 (version, checksum, wfmSize, then the sizes of the sections
 * after the data), a 320-byte WaveHeader5 (type at byte 16, nDim[4] at 68, sfA[4] at 84 (the step per point),
 * dataUnits at 148, dimUnits[4][4] at 152), the data, then the dependency formula, the note, the extended data
 * units, the extended units and the labels of each dimension. The byte order is the one that reads the version as
 * 1, 2, 3 or 5; the 16-bit sum of the 384 header bytes is 0.
 *
 * <p>An image is a wave of nDim[0] x nDim[1] points (x fastest) and, in Asylum's files, nDim[2] layers, one per
 * channel (HeightRetrace, AmplitudeRetrace, PhaseRetrace, ZSensorRetrace, ...), whose names are the labels of
 * dimension 2: 32 bytes each, NUL-terminated, the first naming the dimension itself. A layer's unit is the
 * "NameUnit" of the wave's note, else the one its name implies (Height, ZSensor, Deflection and Amplitude in m,
 * Phase in deg, ...), else the wave's data unit, as Gwyddion reads them. Igor draws y upwards and Gwyddion flips the
 * rows on import; so does this reader, so row 0 is the top of the picture both show.
 */
final class IbwReader {
    private static final int BIN_HEADER_BYTES = 64;
    private static final int WAVE_HEADER_BYTES = 320;
    private static final int HEADERS = BIN_HEADER_BYTES + WAVE_HEADER_BYTES;
    private static final int LABEL_BYTES = 32;
    private static final int MAX_DIMS = 4;

    /** Asylum's layer names and their units, by prefix (after a DAC or Nap prefix), as Gwyddion's igorfile.c. */
    private static final String[][] UNIT_OF_NAME = {
        {"Height", "m"}, {"ZSensor", "m"}, {"Deflection", "m"}, {"Amplitude", "m"}, {"Phase", "deg"},
        {"Current", "A"}, {"Frequency", "Hz"}, {"Capacitance", "F"}, {"Potential", "V"}, {"Count", ""},
        {"QFactor", ""},
    };

    private IbwReader() {
    }

    /** A version 5 header in either byte order whose checksum adds up: an Igor wave whatever its name. */
    static boolean looksLikeIbw(byte[] bytes) {
        if (bytes.length < HEADERS) {
            return false;
        }
        ByteOrder order = byteOrder(bytes);
        return order != null && version(bytes, order) == 5 && checksum(bytes, order) == 0;
    }

    static HeightField read(Path file, byte[] bytes, String channel, Double pixelSizeUm, Reporter reporter) {
        List<ScanChannel> channels = channels(file, bytes);
        return ChannelChoice.choose(file, channels, channel, reporter).heightField(file, pixelSizeUm, reporter);
    }

    /** Every layer of the wave (one for a 2-D wave), by layer index. */
    static List<ScanChannel> channels(Path file, byte[] bytes) {
        if (bytes.length < 2) {
            throw truncated(file, "the file has " + bytes.length + " byte, not even the version");
        }
        ByteOrder order = byteOrder(bytes);
        if (order == null) {
            throw new UserInputException(file + ": not an Igor binary wave (its first two bytes, the version, read as"
                    + " neither 1, 2, 3 nor 5 in either byte order); save the image from Igor or the AFM software as"
                    + " .ibw again");
        }
        int version = version(bytes, order);
        if (version != 5) {
            throw new UserInputException(file + ": an Igor binary wave of version " + version + ", which holds"
                    + " one-dimensional waves only; an image needs version 5 (Igor Pro 3 or later, what Asylum"
                    + " Research AFMs write)");
        }
        if (bytes.length < HEADERS) {
            throw truncated(file, "its headers need " + HEADERS + " bytes, the file has " + bytes.length);
        }
        int sum = checksum(bytes, order);
        if (sum != 0) {
            throw new UserInputException(file + ": the Igor header's checksum does not add up (the 16-bit sum of its "
                    + HEADERS + " bytes is " + sum + ", not 0); the file is damaged or not an Igor binary wave");
        }
        ByteBuffer b = ByteBuffer.wrap(bytes).order(order);

        long wfmSize = Integer.toUnsignedLong(b.getInt(4));
        long[] sectionSizes = new long[1 + 1 + 1 + MAX_DIMS + MAX_DIMS]; // formula, note, data units, dim units, labels
        for (int i = 0; i < sectionSizes.length; i++) {
            sectionSizes[i] = Integer.toUnsignedLong(b.getInt(8 + 4 * i));
        }
        int w = BIN_HEADER_BYTES;
        long points = Integer.toUnsignedLong(b.getInt(w + 12));
        int type = b.getShort(w + 16) & 0xFFFF;
        String waveName = cString(bytes, w + 28, 32);
        int[] nDim = new int[MAX_DIMS];
        double[] step = new double[MAX_DIMS];
        String[] dimUnits = new String[MAX_DIMS];
        for (int d = 0; d < MAX_DIMS; d++) {
            nDim[d] = b.getInt(w + 68 + 4 * d);
            step[d] = b.getDouble(w + 84 + 8 * d);
            dimUnits[d] = cString(bytes, w + 152 + 4 * d, 4);
        }
        String dataUnits = cString(bytes, w + 148, 4);

        SampleType sample = SampleType.of(file, type);
        for (int d = 0; d < MAX_DIMS; d++) {
            if (nDim[d] < 0) {
                throw damaged(file, "nDim[" + d + "] = " + nDim[d] + " is negative");
            }
        }
        if (nDim[1] == 0) {
            throw new UserInputException(file + ": a one-dimensional wave (" + nDim[0] + " points, a curve such as a"
                    + " force curve), not an image; save an image scan");
        }
        if (nDim[3] > 1) {
            throw new UserInputException(file + ": a four-dimensional wave (" + nDim[0] + " x " + nDim[1] + " x "
                    + nDim[2] + " x " + nDim[3] + "), not an image; save an image scan");
        }
        int cols = nDim[0];
        int rows = nDim[1];
        int layers = Math.max(1, nDim[2]);
        long expectedPoints = (long) cols * rows * layers;
        if (points != expectedPoints) {
            throw damaged(file, "npnts = " + points + " does not match its dimensions " + cols + " x " + rows
                    + (nDim[2] > 0 ? " x " + layers : ""));
        }
        long dataBytes = wfmSize - WAVE_HEADER_BYTES;
        if (dataBytes != points * sample.bytes) {
            throw damaged(file, "wfmSize = " + wfmSize + " leaves " + dataBytes + " bytes of data for " + points
                    + " points of " + sample.bytes + " bytes (" + sample.name + ")");
        }
        if (dataBytes > Integer.MAX_VALUE - HEADERS) {
            throw new UserInputException(file + ": a wave of " + points + " points is too large; crop the image");
        }
        long available = bytes.length - (long) HEADERS;
        if (available < dataBytes) {
            throw truncated(file, cols + " x " + rows + (nDim[2] > 0 ? " x " + layers : "") + " points of "
                    + sample.name + " need " + dataBytes + " bytes after the headers, found " + available);
        }

        long after = HEADERS + dataBytes;
        long sectionsBytes = 0;
        for (long size : sectionSizes) {
            sectionsBytes += size;
        }
        if (bytes.length - after < sectionsBytes) {
            throw truncated(file, "the note, units and labels after the data need " + sectionsBytes + " bytes, found "
                    + (bytes.length - after));
        }
        int p = (int) after + (int) sectionSizes[0]; // the dependency formula is of no use here
        String note = new String(bytes, p, (int) sectionSizes[1], StandardCharsets.ISO_8859_1);
        p += (int) sectionSizes[1];
        if (sectionSizes[2] > 0) {
            dataUnits = cString(bytes, p, (int) sectionSizes[2]);
            p += (int) sectionSizes[2];
        }
        for (int d = 0; d < MAX_DIMS; d++) {
            if (sectionSizes[3 + d] > 0) {
                dimUnits[d] = cString(bytes, p, (int) sectionSizes[3 + d]);
                p += (int) sectionSizes[3 + d];
            }
        }
        List<String> layerLabels = List.of();
        for (int d = 0; d < MAX_DIMS; d++) {
            int size = (int) sectionSizes[3 + MAX_DIMS + d];
            if (d == 2) {
                layerLabels = labels(bytes, p, size);
            }
            p += size;
        }

        // One lateral unit for both extents: y converted into x's unit where both are lengths.
        String lateralUnit = dimUnits[0];
        double width = step[0] * cols;
        double height = step[1] * rows;
        if (!dimUnits[1].equals(dimUnits[0])) {
            OptionalDouble x = LengthUnit.micrometres(dimUnits[0]);
            OptionalDouble y = LengthUnit.micrometres(dimUnits[1]);
            if (x.isPresent() && y.isPresent()) {
                height *= y.getAsDouble() / x.getAsDouble();
            } else if (x.isPresent()) {
                lateralUnit = dimUnits[1];
            }
        }

        Map<String, String> noteFields = noteFields(note);
        List<ScanChannel> channels = new ArrayList<>();
        ByteBuffer data = ByteBuffer.wrap(bytes, HEADERS, (int) dataBytes).slice().order(order);
        for (int k = 0; k < layers; k++) {
            String title;
            String unit;
            if (nDim[2] == 0) {
                title = waveName.isEmpty() ? "wave" : waveName;
                unit = dataUnits;
            } else {
                String label = k + 1 < layerLabels.size() ? layerLabels.get(k + 1) : "";
                title = label.isEmpty() ? "layer " + k : label;
                unit = label.isEmpty() ? dataUnits : layerUnit(label, noteFields, dataUnits);
            }
            double[] values = new double[cols * rows];
            int layerStart = k * cols * rows;
            for (int j = 0; j < rows; j++) {
                int row = rows - 1 - j; // Igor's first row is the bottom of the picture
                for (int i = 0; i < cols; i++) {
                    values[row * cols + i] = sample.read(data, (layerStart + j * cols + i) * sample.bytes);
                }
            }
            channels.add(new ScanChannel(k, title, unit, cols, rows, lateralUnit, width, height, values, 0));
        }
        return channels;
    }

    /** The sample types of PTN003 that hold real numbers. */
    private enum SampleType {
        FLOAT32(2, 4, "float32"), FLOAT64(4, 8, "float64"), INT8(0x08, 1, "int8"), INT16(0x10, 2, "int16"),
        INT32(0x20, 4, "int32"), UINT8(0x48, 1, "uint8"), UINT16(0x50, 2, "uint16"), UINT32(0x60, 4, "uint32");

        final int code;
        final int bytes;
        final String name;

        SampleType(int code, int bytes, String name) {
            this.code = code;
            this.bytes = bytes;
            this.name = name;
        }

        static SampleType of(Path file, int code) {
            if (code == 0) {
                throw new UserInputException(file + ": a text wave, not an image of numbers; save the height image");
            }
            if ((code & 1) != 0) {
                throw new UserInputException(file + ": a complex wave (type 0x" + Integer.toHexString(code) + "), not"
                        + " real heights; save the height image");
            }
            for (SampleType t : values()) {
                if (t.code == code) {
                    return t;
                }
            }
            throw damaged(file, "the wave type 0x" + Integer.toHexString(code) + " is none of Igor's number types");
        }

        double read(ByteBuffer data, int at) {
            return switch (this) {
                case FLOAT32 -> data.getFloat(at);
                case FLOAT64 -> data.getDouble(at);
                case INT8 -> data.get(at);
                case INT16 -> data.getShort(at);
                case INT32 -> data.getInt(at);
                case UINT8 -> data.get(at) & 0xFF;
                case UINT16 -> data.getShort(at) & 0xFFFF;
                case UINT32 -> Integer.toUnsignedLong(data.getInt(at));
            };
        }
    }

    /** The byte order in which the version field reads 1, 2, 3 or 5, or null. */
    private static ByteOrder byteOrder(byte[] bytes) {
        if (bytes.length < 2) {
            return null;
        }
        for (ByteOrder order : new ByteOrder[] {ByteOrder.LITTLE_ENDIAN, ByteOrder.BIG_ENDIAN}) {
            int v = version(bytes, order);
            if (v == 1 || v == 2 || v == 3 || v == 5) {
                return order;
            }
        }
        return null;
    }

    private static int version(byte[] bytes, ByteOrder order) {
        return ByteBuffer.wrap(bytes, 0, 2).order(order).getShort() & 0xFFFF;
    }

    /** The 16-bit sum of the headers' 16-bit words, 0 for a sound file (the checksum field makes it so). */
    private static int checksum(byte[] bytes, ByteOrder order) {
        ByteBuffer b = ByteBuffer.wrap(bytes, 0, HEADERS).order(order);
        int sum = 0;
        for (int i = 0; i < HEADERS; i += 2) {
            sum += b.getShort(i) & 0xFFFF;
        }
        return sum & 0xFFFF;
    }

    /** Labels of one dimension: 32-byte fields, each NUL-terminated; the first names the dimension. */
    private static List<String> labels(byte[] bytes, int at, int size) {
        List<String> labels = new ArrayList<>();
        for (int i = 0; i + LABEL_BYTES <= size; i += LABEL_BYTES) {
            labels.add(cString(bytes, at + i, LABEL_BYTES));
        }
        return labels;
    }

    /** Asylum's note: "Key: Value" lines separated by CR (older files) or LF. */
    private static Map<String, String> noteFields(String note) {
        Map<String, String> fields = new HashMap<>();
        for (String line : note.split("[\r\n]+")) {
            int colon = line.indexOf(':');
            if (colon > 0) {
                fields.putIfAbsent(line.substring(0, colon).strip(), line.substring(colon + 1).strip());
            }
        }
        return fields;
    }

    /**
     * A layer's unit: the note's "NameUnit", where Name is the label without its Trace/Retrace (and ModN) ending;
     * else the unit of the name's kind; else the wave's data unit.
     */
    private static String layerUnit(String label, Map<String, String> note, String dataUnits) {
        String name = label;
        int mod = name.indexOf("Mod");
        if (mod > 0 && name.substring(mod + 3).matches("\\d*")) {
            name = name.substring(0, mod);
        }
        if (name.endsWith("Trace")) {
            name = name.substring(0, name.length() - "Trace".length());
        } else if (name.endsWith("Retrace")) {
            name = name.substring(0, name.length() - "Retrace".length());
        }
        String fromNote = note.get(name + "Unit");
        if (fromNote != null) {
            return fromNote;
        }
        String kind = name.startsWith("DAC") || name.startsWith("Nap") ? name.substring(3) : name;
        for (String[] entry : UNIT_OF_NAME) {
            if (kind.toLowerCase(Locale.ROOT).startsWith(entry[0].toLowerCase(Locale.ROOT))) {
                return entry[1];
            }
        }
        return dataUnits;
    }

    private static String cString(byte[] bytes, int at, int max) {
        int end = at;
        while (end < at + max && bytes[end] != 0) {
            end++;
        }
        return new String(bytes, at, end - at, StandardCharsets.ISO_8859_1).strip();
    }

    private static UserInputException truncated(Path file, String detail) {
        return new UserInputException(file + ": truncated Igor binary wave: " + detail + "; copy or save the file"
                + " again");
    }

    private static UserInputException damaged(Path file, String detail) {
        return new UserInputException(file + ": damaged Igor binary wave: " + detail + "; save it from Igor or the"
                + " AFM software again");
    }
}
