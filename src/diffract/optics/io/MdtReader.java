package diffract.optics.io;

import diffract.util.UserInputException;

import java.nio.ByteOrder;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static diffract.optics.io.ReaderSupport.printable;

/**
 * NT-MDT scans (.mdt, as Nova and Nova PX save them; the layout of Gwyddion's nt-mdt module and NT-MDT's own
 * description): a 33-byte file header (the magic 01 B0 93 FF, the size of what follows it, the index of the last
 * frame at byte 12), then frames, each with a 22-byte header (its size, its type, version and date, the size of its
 * variables). Images are read from frames of type 106, "MDA": a header (its size, then after two GUIDs and a status
 * the sizes of the name, the comment, the view, the specification, the source and the variables), the name
 * (cp1251), the comment, the skipped blocks, then the array: its size, cell size and the number of dimensions and
 * measurands, each a calibration (name, unit string, bias, scale, first and last index, sample type), and the
 * samples. An image has two dimensions (x, y) and one measurand; a sample is bias + scale * raw in the measurand's
 * unit, the extent of an axis its scale times its number of points less one. The rows are stored from the bottom
 * up; row 0 of the channel is the top row, as Gwyddion shows it. A channel's index is its frame's. Other frames
 * (text, palettes, spectra, and the classic scanned-data frames of type 0) are not images read here.
 */
final class MdtReader {
    private static final int FILE_HEADER_BYTES = 33;
    private static final int FRAME_HEADER_BYTES = 22;
    private static final int FRAME_SCANNED = 0;
    private static final int FRAME_MDA = 106;
    private static final int MAX_CALIBRATIONS = 16;
    private static final Charset CP1251 = Charset.forName("windows-1251");

    private MdtReader() {
    }

    static boolean looksLikeMdt(byte[] b) {
        return b.length >= 4 && (b[0] & 0xFF) == 0x01 && (b[1] & 0xFF) == 0xB0 && (b[2] & 0xFF) == 0x93
                && (b[3] & 0xFF) == 0xFF;
    }

    private record Calibration(String name, String unit, double bias, double scale, long minIndex, long maxIndex,
                               int type) {
        long points() {
            return maxIndex - minIndex + 1;
        }
    }

    static List<ScanChannel> channels(Path file, byte[] bytes) {
        ScanBytes b = new ScanBytes(file, bytes, ByteOrder.LITTLE_ENDIAN, "NT-MDT");
        b.require(0, FILE_HEADER_BYTES, "the file header");
        int lastFrame = b.u16(12, "the last frame's index");
        long at = FILE_HEADER_BYTES;
        List<ScanChannel> out = new ArrayList<>();
        int scanned = 0;
        for (int frame = 0; frame <= lastFrame; frame++) {
            long size = b.u32(at, "frame " + frame + "'s header");
            int type = b.u16(at + 4, "frame " + frame + "'s header");
            if (size < FRAME_HEADER_BYTES) {
                throw b.damaged("frame " + frame + " claims " + size + " bytes, less than its own header");
            }
            b.require(at, size, "frame " + frame);
            if (type == FRAME_MDA) {
                ScanChannel c = mda(b, at + FRAME_HEADER_BYTES, at + size, frame);
                if (c != null) {
                    out.add(c);
                }
            } else if (type == FRAME_SCANNED) {
                scanned++;
            }
            at += size;
        }
        if (out.isEmpty()) {
            throw new UserInputException(file + ": the NT-MDT file holds no image of the kind read here (MDA frames"
                    + " of two dimensions" + (scanned > 0 ? "; its " + scanned + " classic scanned-data frame"
                    + (scanned == 1 ? " is" : "s are") + " not read" : "") + "); export the topography from Nova or"
                    + " Gwyddion as .gsf");
        }
        return out;
    }

    /** The image of an MDA frame whose variables start at {@code p}, or null when it is no image (a spectrum). */
    private static ScanChannel mda(ScanBytes b, long p, long frameEnd, int frame) {
        String where = "NT-MDT frame " + frame;
        long headSize = b.u32(p, where);
        long nameSize = b.u32(p + 44, where);
        long commentSize = b.u32(p + 48, where);
        long viewSize = b.u32(p + 52, where);
        long specSize = b.u32(p + 56, where);
        long sourceSize = b.u32(p + 60, where);
        long q = p + headSize;
        String name = nameSize > 0 ? b.string(q, Math.min(nameSize, 4096), CP1251, where + "'s name").strip() : "";
        q += nameSize + commentSize + specSize + viewSize + sourceSize;
        q += 4; // the array's total size
        long structLen = b.u32(q, where + "'s array");
        long struct = q + 4;
        long dims = b.u32(struct + 12, where + "'s array");
        long measurands = b.u32(struct + 16, where + "'s array");
        if (dims > MAX_CALIBRATIONS || measurands > MAX_CALIBRATIONS) {
            throw b.damaged(where + " claims " + dims + " dimensions and " + measurands + " measurands");
        }
        q = struct + structLen;
        List<Calibration> calibrations = new ArrayList<>();
        for (int i = 0; i < dims + measurands; i++) {
            long total = b.u32(q, where + "'s calibration " + i);
            calibrations.add(calibration(b, q, where + "'s calibration " + i));
            if (total < 8) {
                throw b.damaged(where + "'s calibration " + i + " claims " + total + " bytes");
            }
            q += total;
        }
        if (dims != 2 || measurands != 1) {
            return null;
        }
        Calibration x = calibrations.get(0);
        Calibration y = calibrations.get(1);
        Calibration z = calibrations.get(2);
        for (Calibration axis : List.of(x, y)) {
            if (axis.minIndex() < 0 || axis.maxIndex() < axis.minIndex()
                    || axis.maxIndex() - axis.minIndex() >= Integer.MAX_VALUE) {
                throw b.damaged(where + "'s axis '" + printable(axis.name()) + "' spans indices " + axis.minIndex()
                        + " to " + axis.maxIndex());
            }
        }
        long cols = x.points();
        long rows = y.points();
        int sampleBytes = switch (z.type()) {
            case -1, 1 -> 1;
            case -2, 2 -> 2;
            case -4, 4, -(4 + 23 * 256) -> 4;
            case -8, 8, -(8 + 52 * 256) -> 8;
            default -> throw new UserInputException(b.file() + ": " + where + " holds samples of type " + z.type()
                    + ", which is not read (integers of 1 to 8 bytes and 32- and 64-bit floats are)");
        };
        String title = name.isEmpty() ? "frame " + frame : name;
        ReaderSupport.requireSize(b.file(), cols, rows, sampleBytes, b.length(), where + " '" + printable(title)
                + "'");
        b.require(q, cols * rows * sampleBytes, where + "'s samples");
        if (q + cols * rows * sampleBytes > frameEnd) {
            throw b.damaged(where + "'s samples run past the frame's end");
        }
        SiUnit lateral = SiUnit.of(x.unit());
        SiUnit unit = SiUnit.of(z.unit());
        double scale = z.scale() * unit.factor();
        double bias = z.bias() * unit.factor();
        if (!Double.isFinite(scale) || !Double.isFinite(bias)) {
            throw b.damaged(where + "'s scale or bias is not a finite number");
        }
        int n = (int) (cols * rows);
        double[] stored = new double[n];
        for (int i = 0; i < n; i++) {
            long s = q + (long) i * sampleBytes;
            double raw = switch (z.type()) {
                case -1 -> (byte) b.u8(s, where);
                case 1 -> b.u8(s, where);
                case -2 -> b.i16(s, where);
                case 2 -> b.u16(s, where);
                case -4 -> b.i32(s, where);
                case 4 -> b.u32(s, where);
                case -8 -> b.i64(s, where);
                case 8 -> unsigned(b.i64(s, where));
                case -(4 + 23 * 256) -> b.f32(s, where);
                default -> b.f64(s, where);
            };
            stored[i] = bias + scale * raw;
        }
        double width = x.scale() * (cols - 1) * lateral.factor();
        double height = y.scale() * (rows - 1) * SiUnit.of(y.unit()).factor();
        return new ScanChannel(frame, title, unit.base(), (int) cols, (int) rows, lateral.base(), Math.abs(width),
                Math.abs(height), ReaderSupport.flippedRows(stored, (int) cols, (int) rows), 0);
    }

    private static double unsigned(long v) {
        return v >= 0 ? v : (v >>> 1) * 2.0 + (v & 1);
    }

    private static Calibration calibration(ScanBytes b, long c, String where) {
        long structLen = b.u32(c + 4, where);
        long nameLen = b.u32(c + 8, where);
        long commentLen = b.u32(c + 12, where);
        long unitLen = b.u32(c + 16, where);
        double bias = b.f64(c + 44, where);
        double scale = b.f64(c + 52, where);
        long min = b.i64(c + 60, where);
        long max = b.i64(c + 68, where);
        int type = b.i32(c + 76, where);
        long text = c + 8 + structLen;
        String name = b.string(text, Math.min(nameLen, 4096), CP1251, where).strip();
        String unit = b.string(text + nameLen + commentLen, Math.min(unitLen, 64), StandardCharsets.ISO_8859_1,
                where).strip();
        return new Calibration(name, unit, bias, scale, min, max, type);
    }
}
