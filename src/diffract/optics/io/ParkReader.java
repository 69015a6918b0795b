package diffract.optics.io;

import diffract.util.UserInputException;

import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.OptionalDouble;

import static diffract.optics.io.ReaderSupport.printable;

/**
 * Park Systems (PSIA) scans (.tiff, as the XE and NX series save them; the layout Gwyddion's psia module reads): a
 * TIFF whose first directory holds a colour preview and private tags: the magic 0x0E031301 (tag 50432), the version
 * 0x01000001 or 0x01000002 (50433), the data (50434: offset and byte count) and the image header (50435), all
 * little-endian. The header: image type (0 for an image), the source name (32 UTF-16 characters: "Topography", ...),
 * the mode (8), the low-pass strength, auto-flatten, AC track, the columns and rows, the angle, sine scan, overscan,
 * forward, scan up, swap x and y, the width and height in micrometres, their offsets, the scan rate, the set point
 * and its unit (8), the tip and sample bias, the data gain, the z scale, the z offset and the z unit (8), ...; from
 * version 2 the sample type (0: int16, 1: int32, 2: float32) stands at byte 348. A sample is
 * (raw * z scale + z offset) * data gain in the z unit; the rows are stored from the bottom up (row 0 of the
 * channel is the top row, as Gwyddion shows it). A scan with swapped axes is turned back as Gwyddion does.
 */
final class ParkReader {
    private static final long MAGIC = 0x0E031301L;
    private static final long VERSION_1 = 0x01000001L;
    private static final long VERSION_2 = 0x01000002L;
    private static final int TAG_MAGIC = 50432;
    private static final int TAG_VERSION = 50433;
    private static final int TAG_DATA = 50434;
    private static final int TAG_HEADER = 50435;

    private ParkReader() {
    }

    static boolean looksLikePark(byte[] bytes) {
        if (!TiffDirectories.looksLikeTiff(bytes)) {
            return false;
        }
        try {
            TiffDirectories tiff = TiffDirectories.read(Path.of("probe"), bytes, "Park Systems TIFF");
            return tiff.integer(0, TAG_MAGIC, 0) == MAGIC;
        } catch (UserInputException e) {
            return false;
        }
    }

    static List<ScanChannel> channels(Path file, byte[] bytes) {
        TiffDirectories tiff = TiffDirectories.read(file, bytes, "Park Systems TIFF");
        if (tiff.integer(0, TAG_MAGIC, 0) != MAGIC) {
            throw new UserInputException(file + ": a TIFF without the Park Systems magic (tag 50432), so not a Park"
                    + " scan; open the .tiff the Park software saved");
        }
        long version = tiff.integer(0, TAG_VERSION, 0);
        if (version != VERSION_1 && version != VERSION_2) {
            throw new UserInputException(file + ": Park Systems TIFF version 0x" + Long.toHexString(version)
                    + ", not 0x1000001 or 0x1000002, which are the versions read");
        }
        TiffDirectories.Entry data = tiff.entry(0, TAG_DATA);
        TiffDirectories.Entry header = tiff.entry(0, TAG_HEADER);
        if (data == null || header == null) {
            throw new UserInputException(file + ": the Park Systems TIFF lacks its " + (data == null ? "data (tag 50434)"
                    : "header (tag 50435)") + "; the file is damaged, save it again");
        }
        ScanBytes b = new ScanBytes(file, bytes, ByteOrder.LITTLE_ENDIAN, "Park Systems TIFF");
        long h = header.valueOffset();
        long headerBytes = header.count();
        long needed = version == VERSION_1 ? 356 : 580;
        if (headerBytes < needed) {
            throw b.damaged("its image header has " + headerBytes + " bytes, version " + (version == VERSION_1 ? 1 : 2)
                    + " needs " + needed);
        }
        b.require(h, needed, "the image header");
        long type = b.u32(h, "the image type");
        if (type != 0) {
            throw new UserInputException(file + ": a Park Systems " + (type == 1 ? "line profile" : type == 2
                    ? "spectroscopy file" : "file of image type " + type) + ", not an image scan");
        }
        String source = utf16(b, h + 4, 32);
        long cols = b.u32(h + 100, "the columns");
        long rows = b.u32(h + 104, "the rows");
        boolean swapXy = b.u32(h + 136, "swap x y") != 0;
        double widthUm = Math.abs(b.f64(h + 140, "the width"));
        double heightUm = Math.abs(b.f64(h + 148, "the height"));
        double dataGain = b.f64(h + 220, "the data gain");
        double zScale = b.f64(h + 228, "the z scale");
        double zOffset = b.f64(h + 236, "the z offset");
        String zUnit = utf16(b, h + 244, 8);
        int sampleType = version == VERSION_2 ? (int) b.u32(h + 348, "the sample type") : 0;
        int sampleBytes = switch (sampleType) {
            case 0 -> 2;
            case 1, 2 -> 4;
            default -> throw b.damaged("its sample type is " + sampleType + " (0 int16, 1 int32, 2 float32)");
        };
        String where = "Park Systems image '" + printable(source) + "'";
        ReaderSupport.requireSize(file, cols, rows, sampleBytes, bytes.length, where);
        long dataOffset = data.valueOffset();
        if (data.count() < cols * rows * sampleBytes) {
            throw b.damaged("its data tag holds " + data.count() + " bytes, " + cols + " x " + rows + " samples of "
                    + sampleBytes + " bytes need " + cols * rows * sampleBytes);
        }
        if (zScale == 0) {
            zScale = 1; // Gwyddion's reading: a zero scale means none
        }
        if (zUnit.isEmpty()) {
            zUnit = "um";
        }
        double toBase = 1;
        String unit = zUnit;
        OptionalDouble um = LengthUnit.micrometres(zUnit);
        if (um.isPresent()) {
            toBase = um.getAsDouble() * 1e-6;
            unit = "m";
        }
        double q = toBase * dataGain;
        if (!Double.isFinite(q) || !Double.isFinite(zScale) || !Double.isFinite(zOffset) || !(widthUm > 0)
                || !(heightUm > 0)) {
            throw b.damaged("its header's scale or size is not a finite number");
        }
        int n = (int) (cols * rows);
        double[] stored = new double[n];
        for (int i = 0; i < n; i++) {
            long at = dataOffset + (long) i * sampleBytes;
            double raw = switch (sampleType) {
                case 0 -> b.i16(at, where);
                case 1 -> b.i32(at, where);
                default -> b.f32(at, where);
            };
            stored[i] = q * zScale * raw + q * zOffset;
        }
        double[] values = ReaderSupport.flippedRows(stored, (int) cols, (int) rows);
        int c = (int) cols;
        int r = (int) rows;
        double width = widthUm * 1e-6;
        double height = heightUm * 1e-6;
        if (swapXy) {
            // turned a quarter anticlockwise, as Gwyddion shows it
            double[] turned = new double[n];
            for (int i = 0; i < c; i++) {
                for (int j = 0; j < r; j++) {
                    turned[i * r + j] = values[j * c + (c - 1 - i)];
                }
            }
            values = turned;
            int t = c;
            c = r;
            r = t;
            double w = width;
            width = height;
            height = w;
        }
        return List.of(new ScanChannel(0, source.isEmpty() ? "image" : source, unit, c, r, "m", width, height, values,
                0));
    }

    /** Up to {@code chars} little-endian UTF-16 characters, to the first NUL. */
    private static String utf16(ScanBytes b, long offset, int chars) {
        String s = b.string(offset, 2L * chars, StandardCharsets.UTF_16LE, "a name");
        int nul = s.indexOf('\0');
        return (nul >= 0 ? s.substring(0, nul) : s).strip();
    }
}
