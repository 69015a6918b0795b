package diffract.optics.io;

import diffract.util.UserInputException;

import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.OptionalDouble;

import static diffract.optics.io.ReaderSupport.printable;

/**
 * Bruker (Digital Instruments, Veeco) NanoScope files as the microscope saves them (.spm, .000, .001, ...;
 * version 4.3 and later, the layout Gwyddion's nanoscope module reads): a text header of CR LF lines from
 * {@code \*File list} to {@code \*File list end}, in sections ({@code \*Scanner list}, {@code \*Ciao scan list},
 * one {@code \*Ciao image list} per channel) of {@code \Key: value} lines, then the binary images. An image list
 * gives {@code Data offset}, {@code Data length}, {@code Bytes/pixel}, {@code Samps/line}, {@code Number of lines},
 * {@code Scan Size: X Y unit} ({@code ~m} is um) and the channel's name and scaling as "at" values:
 * {@code \@2:Image Data: S [Height] "Height"} and {@code \@2:Z scale: V [Sens. Zsens] (0.0067 V/LSB) 440 V}. The
 * bracketed soft scale names a value of the scanner list, {@code \@Sens. Zsens: V 17.9 nm/V}; a sample is
 * {@code raw / 256^(Bytes/pixel) * 440 V * 17.9 nm/V}. Samples are little-endian 16-bit integers (32-bit from
 * version 9.2), stored from the bottom row up; row 0 of the channel is the top row, as Gwyddion shows it. Lengths
 * are converted to metres.
 */
final class NanoscopeReader {
    static final String MAGIC = "\\*File list";
    private static final String TEXT_MAGIC = "?*File list";
    private static final String FORCE_MAGIC = "\\*Force file list";
    private static final String END = "\\*File list end";
    private static final java.util.regex.Pattern NUMBER =
            java.util.regex.Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?");
    /** A header longer than this is no NanoScope header (they are tens of kilobytes). */
    private static final int MAX_HEADER_BYTES = 4 << 20;

    private NanoscopeReader() {
    }

    static boolean looksLikeNanoscope(byte[] bytes) {
        return startsWith(bytes, MAGIC) || startsWith(bytes, TEXT_MAGIC) || startsWith(bytes, FORCE_MAGIC);
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

    /** A header value: the text after the colon, and for "at" values its type, soft scale and hard value. */
    private record Value(String text, String softScale, double hardValue, String hardUnit) {
        static Value parse(String key, String text) {
            if (!key.startsWith("@")) {
                String[] parts = text.strip().split("\\s+", 2);
                double v = number(parts[0]);
                String unit = parts.length > 1 ? parts[1].replaceAll("\\(.*", "").strip() : "";
                return new Value(text.strip(), null, v, unit);
            }
            String rest = text.strip();
            if (rest.length() < 1) {
                return new Value(rest, null, Double.NaN, "");
            }
            rest = rest.substring(1).strip(); // the type letter: V, S or C
            String soft = null;
            if (rest.startsWith("[")) {
                int close = rest.indexOf(']');
                if (close > 0) {
                    soft = rest.substring(1, close).strip();
                    rest = rest.substring(close + 1).strip();
                }
            }
            if (rest.startsWith("(")) {
                int close = rest.indexOf(')');
                rest = close > 0 ? rest.substring(close + 1).strip() : "";
            }
            String[] parts = rest.split("\\s+");
            double v = parts.length > 0 ? number(parts[0]) : Double.NaN;
            String unit = parts.length == 2 ? parts[1] : "";
            return new Value(rest, soft, v, unit);
        }

        private static double number(String s) {
            // checked first: a header holds hundreds of values that are no numbers, and exceptions cost
            if (!NUMBER.matcher(s).matches()) {
                return Double.NaN;
            }
            return Double.parseDouble(s);
        }

        /** The quoted string of a select value, else its text. */
        String selected() {
            int q = text.indexOf('"');
            int end = text.lastIndexOf('"');
            return q >= 0 && end > q ? text.substring(q + 1, end) : text;
        }
    }

    /** A header section: its values' texts by key (lower case), each parsed when it is asked for. */
    private record Section(String name, Map<String, String> values) {
        Value get(String key) {
            String text = values.get(key.toLowerCase(Locale.ROOT));
            return text == null ? null : Value.parse(key, text);
        }
    }

    static List<ScanChannel> channels(Path file, byte[] bytes) {
        if (startsWith(bytes, TEXT_MAGIC)) {
            throw new UserInputException(file + ": a NanoScope file with its data saved as text; save it from the"
                    + " NanoScope software in the binary form (the default) or export it as .gsf from Gwyddion");
        }
        if (startsWith(bytes, FORCE_MAGIC)) {
            throw new UserInputException(file + ": a NanoScope force curve file, not an image scan; open the"
                    + " image scan's file");
        }
        List<Section> sections = header(file, bytes);
        Section fileList = sections.get(0);
        long version = 0;
        Value v = fileList.get("Version");
        if (v != null) {
            try {
                version = Long.parseLong(v.text().replaceFirst("^0[xX]", ""), 16);
            } catch (NumberFormatException e) {
                version = 0;
            }
        }
        int storedBytes = version >= 0x09200000L ? 4 : 2;
        Section scanner = null;
        Section scan = null;
        List<ScanChannel> out = new ArrayList<>();
        int imageIndex = 0;
        for (Section s : sections) {
            String name = s.name().toLowerCase(Locale.ROOT);
            if (name.equals("scanner list") || name.equals("microscope list")) {
                scanner = s;
            } else if (name.equals("ciao scan list") || name.equals("afm list") || name.equals("stm list")
                    || name.equals("nc afm list")) {
                scan = s;
            } else if (name.equals("ciao image list") || name.equals("afm image list")
                    || name.equals("stm image list") || name.equals("ncafm image list") || name.equals("image list")) {
                out.add(channel(file, bytes, s, scanner, scan, imageIndex++, storedBytes));
            }
        }
        if (out.isEmpty()) {
            throw new UserInputException(file + ": the NanoScope header lists no image (no \\*Ciao image list"
                    + " section); open a file that holds an image scan");
        }
        return out;
    }

    private static List<Section> header(Path file, byte[] bytes) {
        int limit = Math.min(bytes.length, MAX_HEADER_BYTES);
        String text = new String(bytes, 0, limit, StandardCharsets.ISO_8859_1);
        int end = text.indexOf(END);
        if (end < 0) {
            throw new UserInputException(file + ": the NanoScope header has no '\\*File list end' line; the file is"
                    + " truncated or damaged, copy it again");
        }
        List<Section> sections = new ArrayList<>();
        Section current = null;
        for (String line : text.substring(0, end).split("\r?\n")) {
            if (line.startsWith("\\*")) {
                current = new Section(line.substring(2).strip(), new java.util.HashMap<>());
                sections.add(current);
            } else if (line.startsWith("\\") && current != null) {
                String body = line.substring(1);
                int from = body.length() > 2 && body.charAt(0) == '@' && Character.isDigit(body.charAt(1))
                        && body.charAt(2) == ':' ? 3 : 0;
                int colon = body.indexOf(':', from);
                if (colon < 0) {
                    continue;
                }
                String key = body.substring(0, colon).strip();
                current.values().putIfAbsent(key.toLowerCase(Locale.ROOT), body.substring(colon + 1));
            } else if (!line.isBlank() && !line.startsWith("\\")) {
                if (line.indexOf('\r') >= 0 || current == null) {
                    continue;
                }
                throw new UserInputException(file + ": NanoScope header line '" + printable(line) + "' does not start"
                        + " with a backslash; the file was damaged, perhaps by a transfer that changed its line"
                        + " endings: copy it again in binary mode");
            }
        }
        if (sections.isEmpty()) {
            throw new UserInputException(file + ": the NanoScope header holds no section; the file is damaged");
        }
        return sections;
    }

    private static ScanChannel channel(Path file, byte[] bytes, Section image, Section scanner, Section scan,
                                       int index, int storedBytes) {
        String where = "NanoScope image " + index;
        long cols = whole(file, image, "Samps/line", where);
        long rows = whole(file, image, "Number of lines", where);
        long offset = whole(file, image, "Data offset", where);
        long length = whole(file, image, "Data length", where);
        Value bpp = image.get("Bytes/pixel");
        int scaleBytes = bpp != null && bpp.hardValue() > 0 && bpp.hardValue() <= 8 ? (int) bpp.hardValue() : 2;
        ReaderSupport.requireSize(file, cols, rows, storedBytes, bytes.length, where);
        if (length < storedBytes * cols * rows) {
            throw new UserInputException(file + ": " + where + " holds " + length + " bytes (Data length), fewer than"
                    + " its " + cols + " x " + rows + " samples of " + storedBytes + " bytes need; the file is damaged");
        }
        ScanBytes b = new ScanBytes(file, bytes, ByteOrder.LITTLE_ENDIAN, "NanoScope");
        b.require(offset, storedBytes * cols * rows, where + "'s samples (Data offset " + offset + ")");

        Value size = image.get("Scan Size");
        if (size == null && scan != null) {
            size = scan.get("Scan Size");
        }
        if (size == null) {
            throw new UserInputException(file + ": " + where + " has no Scan Size; the header is damaged");
        }
        String[] parts = size.text().split("\\s+");
        double width = parts.length > 0 ? Value.number(parts[0]) : Double.NaN;
        double height = parts.length > 2 ? Value.number(parts[1]) : width;
        String lateral = parts.length > 0 ? parts[parts.length - 1].replace("~", "\u00B5") : "";
        if (!(width > 0) || !(height > 0) || !Double.isFinite(width) || !Double.isFinite(height)) {
            throw new UserInputException(file + ": " + where + " has Scan Size '" + printable(size.text())
                    + "', not two positive numbers and a unit; the header is damaged");
        }
        Value aspect = image.get("Aspect ratio");
        if (aspect != null && !aspect.text().equals("1:1") && scan != null && scan.get("Lines") != null
                && scan.get("Lines").hardValue() > 0) {
            height = height * rows / scan.get("Lines").hardValue();
        }

        String title = null;
        Value data = image.get("@2:Image Data");
        if (data == null) {
            data = image.get("@3:Image Data");
        }
        if (data != null) {
            title = data.softScale() != null ? data.softScale() : data.selected();
        } else if (image.get("Image data") != null) {
            title = image.get("Image data").text();
        }
        if (title == null || title.isBlank()) {
            title = "image " + index;
        }

        double scale;
        String unit;
        Value z = image.get("@2:Z scale");
        if (z == null) {
            z = image.get("Z scale");
        }
        if (z == null) {
            throw new UserInputException(file + ": " + where + " ('" + printable(title) + "') has no Z scale; the"
                    + " header is damaged or of a NanoScope version before 4.3, which is not read");
        }
        Value sens = null;
        if (z.softScale() != null) {
            String key = "@" + z.softScale();
            sens = scanner != null ? scanner.get(key) : null;
            if (sens == null && scan != null) {
                sens = scan.get(key);
            }
        }
        if (sens != null && !sens.hardUnit().isEmpty()) {
            scale = z.hardValue() * sens.hardValue();
            String[] fraction = sens.hardUnit().split("/", 2);
            String zUnit = z.hardUnit().isEmpty() ? "V" : z.hardUnit();
            unit = fraction.length == 2 && fraction[1].equals(zUnit) ? fraction[0] : sens.hardUnit() + "*" + zUnit;
        } else if (sens != null) {
            scale = z.hardValue() * sens.hardValue();
            unit = z.softScale().equals("Sens. Phase") ? "deg" : "V";
        } else {
            scale = z.hardValue();
            unit = z.hardUnit();
        }
        unit = unit.replace("~", "\u00B5").replace("\u00BA", "deg");
        if (!Double.isFinite(scale)) {
            throw new UserInputException(file + ": " + where + " ('" + printable(title) + "') has Z scale '"
                    + printable(z.text()) + "', not a number; the header is damaged");
        }
        // a length goes into metres, as Gwyddion keeps it
        OptionalDouble um = LengthUnit.micrometres(unit);
        if (um.isPresent()) {
            scale *= um.getAsDouble() * 1e-6;
            unit = "m";
        }
        double factor = scale / Math.pow(256, scaleBytes);
        int n = (int) (cols * rows);
        double[] stored = new double[n];
        for (int i = 0; i < n; i++) {
            long at = offset + (long) i * storedBytes;
            stored[i] = (storedBytes == 4 ? b.i32(at, where) : b.i16(at, where)) * factor;
        }
        double[] values = ReaderSupport.flippedRows(stored, (int) cols, (int) rows);
        return new ScanChannel(index, title, unit, (int) cols, (int) rows, lateral, width, height, values, 0);
    }

    private static long whole(Path file, Section s, String key, String where) {
        Value v = s.get(key);
        if (v == null || !(v.hardValue() >= 0) || v.hardValue() > Long.MAX_VALUE / 8
                || v.hardValue() != Math.rint(v.hardValue())) {
            throw new UserInputException(file + ": " + where + " has " + (v == null ? "no " + key
                    : key + " '" + printable(v.text()) + "', not a whole number") + "; the header is damaged");
        }
        return (long) v.hardValue();
    }
}
