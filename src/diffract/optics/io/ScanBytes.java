package diffract.optics.io;

import diffract.util.UserInputException;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.Charset;
import java.nio.file.Path;

/**
 * A scan file's bytes read at absolute offsets in one byte order, every read checked against the file's length: a
 * header that points past the end is refused as a truncated or damaged file (one line naming the file, what was
 * read and both sizes), never an index error.
 */
final class ScanBytes {
    private final Path file;
    private final byte[] bytes;
    private final ByteBuffer buffer;
    private final String format;

    /** @param format the format's name for messages ("NanoScope", "TIFF", ...) */
    ScanBytes(Path file, byte[] bytes, ByteOrder order, String format) {
        this.file = file;
        this.bytes = bytes;
        this.buffer = ByteBuffer.wrap(bytes).order(order);
        this.format = format;
    }

    ScanBytes withOrder(ByteOrder order) {
        return new ScanBytes(file, bytes, order, format);
    }

    ByteOrder order() {
        return buffer.order();
    }

    int length() {
        return bytes.length;
    }

    byte[] array() {
        return bytes;
    }

    Path file() {
        return file;
    }

    /** Refuses unless {@code count} bytes from {@code offset} lie inside the file. */
    void require(long offset, long count, String what) {
        if (offset < 0 || count < 0 || offset > bytes.length || count > bytes.length - offset) {
            throw new UserInputException(file + ": truncated or damaged " + format + " file: " + what + " needs "
                    + count + " bytes at byte " + offset + ", the file has " + bytes.length + "; copy or export the"
                    + " file again");
        }
    }

    int u8(long offset, String what) {
        require(offset, 1, what);
        return bytes[(int) offset] & 0xFF;
    }

    int u16(long offset, String what) {
        require(offset, 2, what);
        return buffer.getShort((int) offset) & 0xFFFF;
    }

    int i16(long offset, String what) {
        require(offset, 2, what);
        return buffer.getShort((int) offset);
    }

    long u32(long offset, String what) {
        require(offset, 4, what);
        return Integer.toUnsignedLong(buffer.getInt((int) offset));
    }

    int i32(long offset, String what) {
        require(offset, 4, what);
        return buffer.getInt((int) offset);
    }

    long i64(long offset, String what) {
        require(offset, 8, what);
        return buffer.getLong((int) offset);
    }

    float f32(long offset, String what) {
        require(offset, 4, what);
        return buffer.getFloat((int) offset);
    }

    double f64(long offset, String what) {
        require(offset, 8, what);
        return buffer.getDouble((int) offset);
    }

    String string(long offset, long count, Charset charset, String what) {
        require(offset, count, what);
        return new String(bytes, (int) offset, (int) count, charset);
    }

    /** A NUL-terminated (or full-length) string of at most {@code count} bytes. */
    String cString(long offset, long count, Charset charset, String what) {
        require(offset, count, what);
        int end = (int) offset;
        while (end < offset + count && bytes[end] != 0) {
            end++;
        }
        return new String(bytes, (int) offset, end - (int) offset, charset);
    }

    /** A damaged-file refusal that names the file and the format. */
    UserInputException damaged(String what) {
        return new UserInputException(file + ": damaged " + format + " file: " + what + "; copy or export the file"
                + " again");
    }
}
