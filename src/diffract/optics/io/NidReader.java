package diffract.optics.io;

import diffract.util.UserInputException;

import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import static diffract.optics.io.ReaderSupport.printable;

/**
 * Nanosurf scans (.nid, as easyScan, NaniteAFM and FlexAFM save them): an INI-style text header of
 * {@code [Section]} and {@code Key=Value} lines, then {@code #!} and the binary images one after the other. Section
 * {@code [DataSet]} names the groups ({@code GroupCount}; {@code Gr0-Name=Scan forward}) and in each group its
 * channels ({@code Gr0-Ch1=DataSet-0:1}), in the order their images follow the header. A channel's section gives
 * {@code Points} and {@code Lines}, the extent {@code Dim0Range}, {@code Dim1Range} in {@code Dim0Unit}, the
 * channel's name {@code Dim2Name}, unit {@code Dim2Unit}, {@code Dim2Min} and {@code Dim2Range}, and
 * {@code SaveBits} (16 or 32), {@code SaveSign} and {@code SaveOrder} (Intel: little-endian). A sample is
 * Dim2Min + Dim2Range * (raw - lowest) / 2^bits, lowest the smallest raw value (-2^(bits-1) signed, 0 unsigned).
 * The rows are stored from the bottom up; row 0 of the channel is the top row, as Gwyddion shows it. Channels are
 * numbered from 0 in the order of the header and titled "Z-Axis forward", "Amplitude backward", ...
 */
final class NidReader {
    private static final String MAGIC = "[DataSet]";
    private static final int MAX_HEADER_BYTES = 16 << 20;
    private static final int MAX_CHANNELS = 4096;

    private NidReader() {
    }

    static boolean looksLikeNid(byte[] bytes) {
        int start = bytes.length >= 3 && (bytes[0] & 0xFF) == 0xEF && (bytes[1] & 0xFF) == 0xBB
                && (bytes[2] & 0xFF) == 0xBF ? 3 : 0;
        if (bytes.length < start + MAGIC.length()) {
            return false;
        }
        for (int i = 0; i < MAGIC.length(); i++) {
            if (bytes[start + i] != MAGIC.charAt(i)) {
                return false;
            }
        }
        return true;
    }

    static List<ScanChannel> channels(Path file, byte[] bytes) {
        int end = indexOf(bytes, Math.min(bytes.length, MAX_HEADER_BYTES));
        if (end < 0) {
            throw new UserInputException(file + ": the Nanosurf header does not end with '#!' before the data; the"
                    + " file is truncated or damaged, save it again");
        }
        Map<String, Map<String, String>> sections = parse(new String(bytes, 0, end, StandardCharsets.ISO_8859_1));
        Map<String, String> dataSet = sections.get("dataset");
        if (dataSet == null) {
            throw new UserInputException(file + ": the Nanosurf header has no [DataSet] section; the file is damaged");
        }
        int groups = count(file, dataSet, "GroupCount");
        List<String> channelSections = new ArrayList<>();
        for (int g = 0; g < groups; g++) {
            int slots = count(file, dataSet, "Gr" + g + "-Count");
            for (int c = 0; c < slots && channelSections.size() <= MAX_CHANNELS; c++) {
                String name = dataSet.get(("Gr" + g + "-Ch" + c).toLowerCase(Locale.ROOT));
                if (name != null) {
                    channelSections.add(name);
                }
            }
        }
        if (channelSections.isEmpty() || channelSections.size() > MAX_CHANNELS) {
            throw new UserInputException(file + ": the Nanosurf header lists " + channelSections.size()
                    + " channels; the file holds no image scan or is damaged");
        }
        long at = end + 2L;
        List<ScanChannel> out = new ArrayList<>();
        for (int index = 0; index < channelSections.size(); index++) {
            String sectionName = channelSections.get(index);
            Map<String, String> s = sections.get(sectionName.toLowerCase(Locale.ROOT));
            String where = "Nanosurf channel " + index + " ([" + printable(sectionName) + "])";
            if (s == null) {
                throw new UserInputException(file + ": " + where + " has no section in the header; the file is"
                        + " damaged");
            }
            long cols = whole(file, s, "Points", where);
            long rows = whole(file, s, "Lines", where);
            long bits = whole(file, s, "SaveBits", where);
            if (bits != 16 && bits != 32) {
                throw new UserInputException(file + ": " + where + " has SaveBits " + bits + "; 16 and 32 are read");
            }
            if (!"binary".equalsIgnoreCase(s.getOrDefault("savemode", "Binary"))) {
                throw new UserInputException(file + ": " + where + " is saved as text; save it in binary mode");
            }
            boolean signed = !"unsigned".equalsIgnoreCase(s.getOrDefault("savesign", "Signed"));
            ByteOrder order = "motorola".equalsIgnoreCase(s.getOrDefault("saveorder", "Intel"))
                    ? ByteOrder.BIG_ENDIAN : ByteOrder.LITTLE_ENDIAN;
            int sampleBytes = (int) bits / 8;
            ReaderSupport.requireSize(file, cols, rows, sampleBytes, bytes.length, where);
            double width = real(file, s, "Dim0Range", where);
            double height = real(file, s, "Dim1Range", where);
            double min = real(file, s, "Dim2Min", where);
            double range = real(file, s, "Dim2Range", where);
            SiUnit lateral = SiUnit.of(s.getOrDefault("dim0unit", "m"));
            SiUnit z = SiUnit.of(s.getOrDefault("dim2unit", ""));
            ScanBytes b = new ScanBytes(file, bytes, order, "Nanosurf");
            long size = cols * rows * sampleBytes;
            b.require(at, size, where + "'s samples");
            double lowest = signed ? -Math.pow(2, bits - 1) : 0;
            double step = range / Math.pow(2, bits);
            int n = (int) (cols * rows);
            double[] stored = new double[n];
            for (int i = 0; i < n; i++) {
                long p = at + (long) i * sampleBytes;
                double raw = bits == 16 ? (signed ? b.i16(p, where) : b.u16(p, where))
                        : (signed ? b.i32(p, where) : b.u32(p, where));
                stored[i] = (min + step * (raw - lowest)) * z.factor();
            }
            at += size;
            String frame = s.getOrDefault("frame", "");
            String direction = frame.toLowerCase(Locale.ROOT).startsWith("scan ") ? frame.substring(5) : frame;
            String title = (s.getOrDefault("dim2name", "channel " + index) + " " + direction).strip();
            out.add(new ScanChannel(index, title, z.base(), (int) cols, (int) rows, lateral.base(),
                    width * lateral.factor(), height * lateral.factor(),
                    ReaderSupport.flippedRows(stored, (int) cols, (int) rows), 0));
        }
        return out;
    }

    /** Sections by lower-case name, their keys in lower case. */
    private static Map<String, Map<String, String>> parse(String header) {
        Map<String, Map<String, String>> sections = new HashMap<>();
        Map<String, String> current = null;
        for (String raw : header.split("\r?\n")) {
            String line = raw.strip();
            if (line.startsWith("[") && line.endsWith("]")) {
                current = sections.computeIfAbsent(line.substring(1, line.length() - 1).toLowerCase(Locale.ROOT),
                        k -> new HashMap<>());
            } else if (current != null && line.indexOf('=') > 0) {
                int eq = line.indexOf('=');
                current.putIfAbsent(line.substring(0, eq).strip().toLowerCase(Locale.ROOT),
                        line.substring(eq + 1).strip());
            }
        }
        return sections;
    }

    private static int indexOf(byte[] bytes, int limit) {
        for (int i = 0; i + 1 < limit; i++) {
            if (bytes[i] == '#' && bytes[i + 1] == '!') {
                return i;
            }
        }
        return -1;
    }

    private static int count(Path file, Map<String, String> s, String key) {
        long n = whole(file, s, key, "the [DataSet] section");
        if (n > MAX_CHANNELS) {
            throw new UserInputException(file + ": the Nanosurf header's " + key + " is " + n + "; the file is"
                    + " damaged");
        }
        return (int) n;
    }

    private static long whole(Path file, Map<String, String> s, String key, String where) {
        String v = s.get(key.toLowerCase(Locale.ROOT));
        try {
            long n = Long.parseLong(v == null ? "" : v.strip());
            if (n >= 0) {
                return n;
            }
        } catch (NumberFormatException e) {
            // refused below
        }
        throw new UserInputException(file + ": " + where + " has " + (v == null ? "no " + key : key + " = '"
                + printable(v) + "', not a whole number") + "; the header is damaged");
    }

    private static double real(Path file, Map<String, String> s, String key, String where) {
        String v = s.get(key.toLowerCase(Locale.ROOT));
        try {
            double x = Double.parseDouble(v == null ? "" : v.strip());
            if (Double.isFinite(x)) {
                return x;
            }
        } catch (NumberFormatException e) {
            // refused below
        }
        throw new UserInputException(file + ": " + where + " has " + (v == null ? "no " + key : key + " = '"
                + printable(v) + "', not a number") + "; the header is damaged");
    }
}
