package diffract.optics.io;

import diffract.util.UserInputException;

import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The image file directories of a classic TIFF file (TIFF 6.0, Adobe 1992): the byte order ("II" little-endian,
 * "MM" big-endian), the magic 42, the offset of the first directory; a directory is a 16-bit entry count, 12-byte
 * entries (tag, type, count, and the value itself when it fits in 4 bytes, else its offset) and the offset of the
 * next directory (0 ends the chain). JPK and Park Systems keep their scans' scaling in private tags of such
 * directories; grey images are TIFF too. Every offset and count is checked against the file before it is used, and
 * a chain that loops or runs to more than {@link #MAX_DIRECTORIES} directories is refused.
 */
final class TiffDirectories {
    static final int MAX_DIRECTORIES = 4096;
    private static final int MAX_ENTRIES = 4096;

    /** The tags the readers use. */
    static final int IMAGE_WIDTH = 256;
    static final int IMAGE_LENGTH = 257;
    static final int BITS_PER_SAMPLE = 258;
    static final int COMPRESSION = 259;
    static final int PHOTOMETRIC = 262;
    static final int STRIP_OFFSETS = 273;
    static final int SAMPLES_PER_PIXEL = 277;
    static final int ROWS_PER_STRIP = 278;
    static final int STRIP_BYTE_COUNTS = 279;
    static final int TILE_WIDTH = 322;
    static final int SAMPLE_FORMAT = 339;

    /** One entry: its type, count, and where its value lies in the file. */
    record Entry(int tag, int type, long count, long valueOffset) {
        /** Bytes per item of the TIFF type, 0 for an unknown type. */
        static int itemBytes(int type) {
            return switch (type) {
                case 1, 2, 6, 7 -> 1;   // BYTE, ASCII, SBYTE, UNDEFINED
                case 3, 8 -> 2;         // SHORT, SSHORT
                case 4, 9, 11, 13 -> 4; // LONG, SLONG, FLOAT, IFD
                case 5, 10, 12 -> 8;    // RATIONAL, SRATIONAL, DOUBLE
                default -> 0;
            };
        }
    }

    private final ScanBytes bytes;
    private final List<Map<Integer, Entry>> directories;

    private TiffDirectories(ScanBytes bytes, List<Map<Integer, Entry>> directories) {
        this.bytes = bytes;
        this.directories = directories;
    }

    /** "II*\0" or "MM\0*": a classic TIFF header. */
    static boolean looksLikeTiff(byte[] b) {
        return b.length >= 8 && (b[0] == 'I' && b[1] == 'I' && b[2] == 42 && b[3] == 0
                || b[0] == 'M' && b[1] == 'M' && b[2] == 0 && b[3] == 42);
    }

    /**
     * @param format the format's name in messages ("JPK", "Park Systems TIFF", "TIFF image")
     * @throws UserInputException for a file that is no TIFF or whose directories lie outside it
     */
    static TiffDirectories read(Path file, byte[] raw, String format) {
        if (!looksLikeTiff(raw)) {
            throw new UserInputException(file + ": not a TIFF file (it does not start with II*\\0 or MM\\0*);"
                    + " save it from the instrument's software again");
        }
        ByteOrder order = raw[0] == 'I' ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN;
        ScanBytes b = new ScanBytes(file, raw, order, format);
        List<Map<Integer, Entry>> dirs = new ArrayList<>();
        Set<Long> seen = new HashSet<>();
        long offset = b.u32(4, "the first directory's offset");
        while (offset != 0) {
            if (!seen.add(offset) || dirs.size() >= MAX_DIRECTORIES) {
                throw b.damaged("its chain of image directories loops or holds more than " + MAX_DIRECTORIES);
            }
            int n = b.u16(offset, "directory " + dirs.size());
            if (n > MAX_ENTRIES) {
                throw b.damaged("directory " + dirs.size() + " claims " + n + " entries");
            }
            b.require(offset + 2, 12L * n + 4, "directory " + dirs.size() + "'s " + n + " entries");
            Map<Integer, Entry> entries = new LinkedHashMap<>();
            for (int i = 0; i < n; i++) {
                long e = offset + 2 + 12L * i;
                int tag = b.u16(e, "an entry");
                int type = b.u16(e + 2, "an entry");
                long count = b.u32(e + 4, "an entry");
                int item = Entry.itemBytes(type);
                if (item == 0) {
                    continue; // an unknown type: TIFF readers skip such entries
                }
                long size = item * count;
                long valueOffset = size <= 4 ? e + 8 : b.u32(e + 8, "an entry");
                b.require(valueOffset, size, "tag " + tag + " of directory " + dirs.size());
                entries.putIfAbsent(tag, new Entry(tag, type, count, valueOffset));
            }
            dirs.add(entries);
            offset = b.u32(offset + 2 + 12L * n, "the next directory's offset");
        }
        if (dirs.isEmpty()) {
            throw b.damaged("it holds no image directory");
        }
        return new TiffDirectories(b, dirs);
    }

    int count() {
        return directories.size();
    }

    ScanBytes bytes() {
        return bytes;
    }

    Entry entry(int dir, int tag) {
        return directories.get(dir).get(tag);
    }

    boolean has(int dir, int tag) {
        return entry(dir, tag) != null;
    }

    /** Item {@code i} of an integer entry (BYTE, SHORT, LONG and their signed forms) as a long. */
    long integer(Entry e, long i) {
        long at = e.valueOffset() + i * Entry.itemBytes(e.type());
        return switch (e.type()) {
            case 1, 7 -> bytes.u8(at, "tag " + e.tag());
            case 6 -> (byte) bytes.u8(at, "tag " + e.tag());
            case 3 -> bytes.u16(at, "tag " + e.tag());
            case 8 -> bytes.i16(at, "tag " + e.tag());
            case 4, 13 -> bytes.u32(at, "tag " + e.tag());
            case 9 -> bytes.i32(at, "tag " + e.tag());
            default -> throw bytes.damaged("tag " + e.tag() + " is of type " + e.type() + ", not a whole number");
        };
    }

    /** The first item of an integer tag, or {@code fallback} when the directory lacks it. */
    long integer(int dir, int tag, long fallback) {
        Entry e = entry(dir, tag);
        if (e == null || e.count() < 1) {
            return fallback;
        }
        return integer(e, 0);
    }

    /** The first item of a number tag (any numeric type) as a double, or null when the directory lacks it. */
    Double real(int dir, int tag) {
        Entry e = entry(dir, tag);
        if (e == null || e.count() < 1) {
            return null;
        }
        long at = e.valueOffset();
        return switch (e.type()) {
            case 11 -> (double) bytes.f32(at, "tag " + tag);
            case 12 -> bytes.f64(at, "tag " + tag);
            case 5 -> (double) bytes.u32(at, "tag " + tag) / bytes.u32(at + 4, "tag " + tag);
            case 10 -> (double) bytes.i32(at, "tag " + tag) / bytes.i32(at + 4, "tag " + tag);
            case 2 -> null;
            default -> (double) integer(e, 0);
        };
    }

    /** An ASCII tag without its NUL, or null when the directory lacks it. */
    String string(int dir, int tag) {
        Entry e = entry(dir, tag);
        if (e == null || e.type() != 2) {
            return null;
        }
        return bytes.cString(e.valueOffset(), e.count(), StandardCharsets.UTF_8, "tag " + tag);
    }

    /** Image width and length of a directory (0 when absent). */
    long width(int dir) {
        return integer(dir, IMAGE_WIDTH, 0);
    }

    long length(int dir) {
        return integer(dir, IMAGE_LENGTH, 0);
    }

    /**
     * The samples of an uncompressed one-sample-per-pixel grey directory of 8, 16 or 32 bits (unsigned, signed or
     * float by its SampleFormat), row by row from the first row stored, each as {@code raw * scale + offset}.
     *
     * @param what the channel in messages
     */
    double[] samples(int dir, String what, double scale, double offset) {
        long cols = width(dir);
        long rows = length(dir);
        int bits = (int) integer(dir, BITS_PER_SAMPLE, 1);
        int format = (int) integer(dir, SAMPLE_FORMAT, 1);
        if (integer(dir, COMPRESSION, 1) != 1) {
            throw new UserInputException(bytes.file() + ": " + what + " is compressed (TIFF compression "
                    + integer(dir, COMPRESSION, 1) + "); only uncompressed scans are read, save it uncompressed");
        }
        if (integer(dir, SAMPLES_PER_PIXEL, 1) != 1 || has(dir, TILE_WIDTH)) {
            throw new UserInputException(bytes.file() + ": " + what + " is not one grey sample per pixel in strips;"
                    + " save the scan from the instrument's software again");
        }
        if (bits != 8 && bits != 16 && bits != 32 || format == 3 && bits != 32 || format < 1 || format > 3) {
            throw bytes.damaged(what + " has " + bits + "-bit samples of format " + format
                    + " (8, 16 or 32-bit integers and 32-bit floats are read)");
        }
        int sampleBytes = bits / 8;
        ReaderSupport.requireSize(bytes.file(), cols, rows, sampleBytes, bytes.length(), what);
        Entry offsets = entry(dir, STRIP_OFFSETS);
        if (offsets == null) {
            throw bytes.damaged(what + " has no StripOffsets");
        }
        long rowsPerStrip = Math.max(1, Math.min(integer(dir, ROWS_PER_STRIP, rows), rows));
        long strips = (rows + rowsPerStrip - 1) / rowsPerStrip;
        if (offsets.count() < strips) {
            throw bytes.damaged(what + " has " + offsets.count() + " strips, " + rows + " rows of "
                    + rowsPerStrip + " per strip need " + strips);
        }
        long rowBytes = cols * sampleBytes;
        double[] out = new double[(int) (cols * rows)];
        for (long s = 0; s < strips; s++) {
            long start = integer(offsets, s);
            long rowsHere = Math.min(rowsPerStrip, rows - s * rowsPerStrip);
            bytes.require(start, rowsHere * rowBytes, what + "'s strip " + s);
            for (long r = 0; r < rowsHere; r++) {
                long row = s * rowsPerStrip + r;
                long at = start + r * rowBytes;
                int base = (int) (row * cols);
                for (int c = 0; c < cols; c++) {
                    long p = at + (long) c * sampleBytes;
                    double raw = switch (bits) {
                        case 8 -> format == 2 ? (byte) bytes.u8(p, what) : bytes.u8(p, what);
                        case 16 -> format == 2 ? bytes.i16(p, what) : bytes.u16(p, what);
                        default -> format == 3 ? bytes.f32(p, what) : format == 2 ? bytes.i32(p, what)
                                : bytes.u32(p, what);
                    };
                    out[base + c] = raw * scale + offset;
                }
            }
        }
        return out;
    }
}
