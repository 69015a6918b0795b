package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.util.Reporter;
import diffract.util.UserInputException;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static diffract.optics.io.ReaderSupport.printable;

/**
 * Gwyddion's native files (.gwy, https://gwyddion.net/documentation/user-guide-en/gwyfile-format.html): the magic
 * {@code GWYP}, then one serialised GwyContainer. An object is its NUL-terminated type name, a uint32 byte count of
 * its components and the components, each a NUL-terminated name, a type character (b boolean, c char, i int32,
 * q int64, d double, s NUL-terminated string, o object; capitals for arrays, a uint32 count then the items) and its
 * data; everything little-endian. The container holds channel N as a GwyDataField at "/N/data" (xres, yres, xreal,
 * yreal, si_unit_xy and si_unit_z as GwySIUnit objects with a "unitstr", data as xres x yres doubles row by row
 * from the top), its title at "/N/data/title" and its mask, if any, at "/N/mask".
 */
final class GwyReader {
    static final String MAGIC = "GWYP";
    /** Gwyddion 1's format, which nobody writes any more. */
    private static final String OLD_MAGIC = "GWYO";
    /** Deeper nesting than Gwyddion ever writes (a container of objects of units): a damaged or hostile file. */
    private static final int MAX_DEPTH = 32;
    private static final Pattern CHANNEL_KEY = Pattern.compile("/(\\d{1,9})/data");

    private GwyReader() {
    }

    static boolean looksLikeGwy(byte[] bytes) {
        return startsWith(bytes, MAGIC) || startsWith(bytes, OLD_MAGIC);
    }

    static HeightField read(Path file, byte[] bytes, String channel, Double pixelSizeUm, Reporter reporter) {
        List<ScanChannel> channels = channels(file, bytes, reporter);
        return ChannelChoice.choose(file, channels, channel, reporter).heightField(file, pixelSizeUm, reporter);
    }

    /** Every data field of the file, by channel number. */
    static List<ScanChannel> channels(Path file, byte[] bytes, Reporter reporter) {
        if (startsWith(bytes, OLD_MAGIC)) {
            throw new UserInputException(file + ": a Gwyddion 1 file (magic GWYO), a format no longer read; open it"
                    + " in Gwyddion 2 and save it again");
        }
        if (!startsWith(bytes, MAGIC)) {
            throw new UserInputException(file + ": not a Gwyddion file (it must begin with GWYP); save the data from"
                    + " Gwyddion as .gwy again");
        }
        Cursor cursor = new Cursor(file, bytes, MAGIC.length(), bytes.length);
        GwyObject container = cursor.object("the top-level object", 0);
        if (!container.type.equals("GwyContainer")) {
            throw new UserInputException(file + ": the top-level object is a " + container.type + ", not the"
                    + " GwyContainer a Gwyddion file holds; save the data from Gwyddion as .gwy again");
        }
        if (cursor.pos < bytes.length) {
            reporter.warn(file + ": ignoring " + (bytes.length - cursor.pos) + " bytes after the GwyContainer");
        }
        List<ScanChannel> channels = new ArrayList<>();
        for (Map.Entry<String, Component> entry : container.components.entrySet()) {
            Matcher key = CHANNEL_KEY.matcher(entry.getKey());
            if (key.matches()) {
                int index = Integer.parseInt(key.group(1));
                channels.add(channel(file, container, index));
            }
        }
        if (channels.isEmpty()) {
            throw new UserInputException(file + ": the file holds no image (no GwyDataField at /0/data, /1/data, ...);"
                    + " save an image channel from Gwyddion");
        }
        channels.sort(Comparator.comparingInt(ScanChannel::index));
        return channels;
    }

    private static ScanChannel channel(Path file, GwyObject container, int index) {
        String key = "/" + index + "/data";
        GwyObject field = dataField(file, container, key);
        Component title = container.components.get(key + "/title");
        String name = title == null ? "untitled" : text(file, key + "/title", title);
        int cols = positive(file, key, field, "xres");
        int rows = positive(file, key, field, "yres");
        double[] data = data(file, key, field, cols, rows);
        double xReal = (Double) field.require(file, key, "xreal", 'd');
        double yReal = (Double) field.require(file, key, "yreal", 'd');
        String unitXy = unit(file, key, field, "si_unit_xy");
        String unitZ = unit(file, key, field, "si_unit_z");
        int masked = 0;
        String maskKey = "/" + index + "/mask";
        if (container.components.containsKey(maskKey)) {
            GwyObject mask = dataField(file, container, maskKey);
            Component xres = mask.components.get("xres");
            Component yres = mask.components.get("yres");
            // a mask of another size belongs to nothing Gwyddion would show; only a matching one marks samples
            if (xres != null && yres != null && Integer.valueOf(cols).equals(xres.value)
                    && Integer.valueOf(rows).equals(yres.value)) {
                for (double m : data(file, maskKey, mask, cols, rows)) {
                    if (m != 0) {
                        masked++;
                    }
                }
            }
        }
        return new ScanChannel(index, name, unitZ, cols, rows, unitXy, xReal, yReal, data, masked);
    }

    private static GwyObject dataField(Path file, GwyObject container, String key) {
        GwyObject field = (GwyObject) container.components.get(key).expect(file, key, 'o');
        if (!field.type.equals("GwyDataField")) {
            throw new UserInputException(file + ": '" + key + "' is a " + field.type + ", expected a GwyDataField;"
                    + " the file is damaged or not written by Gwyddion");
        }
        return field;
    }

    private static int positive(Path file, String key, GwyObject field, String name) {
        int value = (Integer) field.require(file, key, name, 'i');
        if (value <= 0) {
            throw new UserInputException(file + ": '" + key + "' has " + name + " = " + value + ", so no samples;"
                    + " save a non-empty image");
        }
        return value;
    }

    private static double[] data(Path file, String key, GwyObject field, int cols, int rows) {
        double[] data = (double[]) field.require(file, key, "data", 'D');
        if (data.length != (long) cols * rows) {
            throw new UserInputException(file + ": '" + key + "' holds " + data.length + " values for xres x yres = "
                    + cols + " x " + rows + "; the file is damaged, save it from Gwyddion again");
        }
        return data;
    }

    /** A GwySIUnit's string; a field without one is unitless, as in Gwyddion. */
    private static String unit(Path file, String key, GwyObject field, String name) {
        Component component = field.components.get(name);
        if (component == null) {
            return "";
        }
        GwyObject unit = (GwyObject) component.expect(file, key + "/" + name, 'o');
        Component text = unit.components.get("unitstr");
        return text == null ? "" : text(file, key + "/" + name + "/unitstr", text);
    }

    /** A string, or a one-character one stored as a character (the Python package gwyfile writes "Z" so). */
    private static String text(Path file, String where, Component component) {
        if (component.type == 'c') {
            return new String(new byte[] {(Byte) component.value}, StandardCharsets.ISO_8859_1);
        }
        return (String) component.expect(file, where, 's');
    }

    private static boolean startsWith(byte[] bytes, String magic) {
        if (bytes.length < magic.length()) {
            return false;
        }
        for (int i = 0; i < magic.length(); i++) {
            if (bytes[i] != magic.charAt(i)) {
                return false;
            }
        }
        return true;
    }

    /** A deserialised object: its type name and its components by name, in file order. */
    private record GwyObject(String type, Map<String, Component> components) {
        Object require(Path file, String key, String name, char type) {
            Component component = components.get(name);
            if (component == null) {
                throw new UserInputException(file + ": '" + key + "' lacks its '" + name + "'; the file is damaged,"
                        + " save it from Gwyddion again");
            }
            return component.expect(file, key + "/" + name, type);
        }
    }

    /** One component's type character and value (Boolean, Byte, Integer, Long, Double, String, GwyObject, arrays). */
    private record Component(char type, Object value) {
        Object expect(Path file, String where, char expected) {
            if (type != expected) {
                throw new UserInputException(file + ": '" + where + "' is of type '" + type + "' (" + typeName(type)
                        + "), expected '" + expected + "' (" + typeName(expected) + "); the file is damaged or not"
                        + " written by Gwyddion");
            }
            return value;
        }
    }

    private static String typeName(char type) {
        return switch (type) {
            case 'b' -> "a boolean";
            case 'c' -> "a character";
            case 'i' -> "a 32-bit integer";
            case 'q' -> "a 64-bit integer";
            case 'd' -> "a double";
            case 's' -> "a string";
            case 'o' -> "an object";
            case 'C' -> "characters";
            case 'I' -> "32-bit integers";
            case 'Q' -> "64-bit integers";
            case 'D' -> "doubles";
            case 'S' -> "strings";
            case 'O' -> "objects";
            default -> "unknown";
        };
    }

    /** Reads within [pos, end); every read checks that the bytes are there. */
    private static final class Cursor {
        private final Path file;
        private final byte[] bytes;
        private final ByteBuffer buffer;
        private int pos;
        private int end;

        Cursor(Path file, byte[] bytes, int pos, int end) {
            this.file = file;
            this.bytes = bytes;
            this.buffer = ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN);
            this.pos = pos;
            this.end = end;
        }

        GwyObject object(String what, int depth) {
            if (depth > MAX_DEPTH) {
                throw new UserInputException(file + ": objects nest deeper than " + MAX_DEPTH + " levels at byte "
                        + pos + "; the file is damaged");
            }
            int start = pos;
            String type = printable(string("the type name of " + what)); // it goes into one-line messages
            long size = uint32("the size of " + type);
            if (size > end - pos) {
                throw truncated(type + " at byte " + start + " says it holds " + size + " bytes, but "
                        + (end == bytes.length ? "the file ends after " : "its parent ends after ") + (end - pos));
            }
            int objectEnd = pos + (int) size;
            int parentEnd = end;
            end = objectEnd;
            Map<String, Component> components = new LinkedHashMap<>();
            while (pos < objectEnd) {
                String name = string("a component name of " + type);
                char kind = (char) u8("the type of " + type + "'s '" + printable(name) + "'");
                Component component = new Component(kind, value(type, name, kind, depth));
                if (components.putIfAbsent(name, component) != null) {
                    throw new UserInputException(file + ": " + type + " holds '" + printable(name) + "' twice; the"
                            + " file is damaged");
                }
            }
            end = parentEnd;
            return new GwyObject(type, components);
        }

        private Object value(String owner, String name, char kind, int depth) {
            String what = owner + "'s '" + printable(name) + "'";
            switch (kind) {
                case 'b':
                    return u8(what) != 0;
                case 'c':
                    return (byte) u8(what);
                case 'i':
                    need(4, what);
                    pos += 4;
                    return buffer.getInt(pos - 4);
                case 'q':
                    need(8, what);
                    pos += 8;
                    return buffer.getLong(pos - 8);
                case 'd':
                    need(8, what);
                    pos += 8;
                    return buffer.getDouble(pos - 8);
                case 's':
                    return string(what);
                case 'o':
                    return object(what, depth + 1);
                case 'C': {
                    int n = count(what, 1);
                    byte[] out = new byte[n];
                    System.arraycopy(bytes, pos, out, 0, n);
                    pos += n;
                    return out;
                }
                case 'I': {
                    int n = count(what, 4);
                    int[] out = new int[n];
                    for (int i = 0; i < n; i++, pos += 4) {
                        out[i] = buffer.getInt(pos);
                    }
                    return out;
                }
                case 'Q': {
                    int n = count(what, 8);
                    long[] out = new long[n];
                    for (int i = 0; i < n; i++, pos += 8) {
                        out[i] = buffer.getLong(pos);
                    }
                    return out;
                }
                case 'D': {
                    int n = count(what, 8);
                    double[] out = new double[n];
                    for (int i = 0; i < n; i++, pos += 8) {
                        out[i] = buffer.getDouble(pos);
                    }
                    return out;
                }
                case 'S': {
                    int n = count(what, 1);
                    String[] out = new String[n];
                    for (int i = 0; i < n; i++) {
                        out[i] = string(what);
                    }
                    return out;
                }
                case 'O': {
                    int n = count(what, 5);
                    GwyObject[] out = new GwyObject[n];
                    for (int i = 0; i < n; i++) {
                        out[i] = object(what, depth + 1);
                    }
                    return out;
                }
                default:
                    throw new UserInputException(file + ": " + what + " at byte " + (pos - 1) + " has the unknown"
                            + " type '" + printable(String.valueOf(kind)) + "'; the file is damaged or not a Gwyddion"
                            + " file");
            }
        }

        /** An array's item count, checked against the bytes left (each item at least {@code itemBytes}). */
        private int count(String what, int itemBytes) {
            long n = uint32("the length of " + what);
            if (n * itemBytes > end - pos) {
                throw truncated(what + " says it holds " + n + " items (" + n * itemBytes + (itemBytes == 1 ? "" : "+")
                        + " bytes), but only " + (end - pos) + " bytes are left");
            }
            return (int) n;
        }

        private String string(String what) {
            for (int i = pos; i < end; i++) {
                if (bytes[i] == 0) {
                    String s = new String(bytes, pos, i - pos, StandardCharsets.UTF_8);
                    pos = i + 1;
                    return s;
                }
            }
            throw truncated(what + " at byte " + pos + " has no terminating NUL");
        }

        private long uint32(String what) {
            need(4, what);
            pos += 4;
            return Integer.toUnsignedLong(buffer.getInt(pos - 4));
        }

        private int u8(String what) {
            need(1, what);
            return bytes[pos++] & 0xFF;
        }

        private void need(int n, String what) {
            if (end - pos < n) {
                throw truncated(what + " at byte " + pos + " needs " + n + " bytes, "
                        + (end == bytes.length ? "the file ends" : "its object ends") + " after " + (end - pos));
            }
        }

        private UserInputException truncated(String detail) {
            return new UserInputException(file + ": truncated or damaged .gwy: " + detail + "; copy or save the file"
                    + " again");
        }
    }
}
