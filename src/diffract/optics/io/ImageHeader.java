package diffract.optics.io;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Path;

/**
 * The pixel size an image's header declares, read before any decoder runs: a PNG's IHDR (width and height,
 * big-endian, at bytes 16 and 20), a BMP's info header (width and height, little-endian, at bytes 18 and 22; a
 * negative height means top-down rows), a TIFF's first directory (ImageWidth, ImageLength). A decoder allocates
 * the whole raster from these numbers, so a small file declaring 40000 x 40000 pixels is refused here, at once, by
 * the heap it would need, instead of after seconds of decoding and an exhausted heap. A header that does not say
 * (no IHDR chunk first) is left to the decoder, which refuses it as corrupt.
 */
final class ImageHeader {
    /** Bytes of the heap one pixel takes beyond the decoded raster: normalised grey and heights, 8 bytes each. */
    private static final long HEAP_BYTES_PER_PIXEL = 16;

    private ImageHeader() {
    }

    static boolean looksLikePngOrBmp(byte[] b) {
        return b.length >= 4 && (b[0] & 0xFF) == 0x89 && b[1] == 'P' && b[2] == 'N' && b[3] == 'G'
                || b.length >= 2 && b[0] == 'B' && b[1] == 'M';
    }

    /**
     * Refuses an image whose declared size cannot be decoded into the heap (the raster at up to 8 bytes a pixel,
     * plus the heights), or holds more pixels than one array; a header too short to say lets the decoder refuse.
     */
    static void requireDecodable(Path file, byte[] b) {
        long width;
        long height;
        long rasterBytesPerPixel = 8; // up to four 16-bit samples
        if (b.length >= 24 && (b[0] & 0xFF) == 0x89 && b[1] == 'P' && b[2] == 'N' && b[3] == 'G'
                && b[12] == 'I' && b[13] == 'H' && b[14] == 'D' && b[15] == 'R') {
            ByteBuffer buf = ByteBuffer.wrap(b).order(ByteOrder.BIG_ENDIAN);
            width = Integer.toUnsignedLong(buf.getInt(16));
            height = Integer.toUnsignedLong(buf.getInt(20));
        } else if (b.length >= 26 && b[0] == 'B' && b[1] == 'M') {
            ByteBuffer buf = ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN);
            width = Math.abs((long) buf.getInt(18));
            height = Math.abs((long) buf.getInt(22));
        } else if (TiffDirectories.looksLikeTiff(b)) {
            TiffDirectories tiff = TiffDirectories.read(file, b, "TIFF image");
            width = tiff.width(0);
            height = tiff.length(0);
        } else {
            return;
        }
        if (width == 0 || height == 0) {
            return; // the decoder says what is wrong
        }
        ReaderSupport.requireSize(file, width, height, 0, b.length, "the image");
        diffract.util.MemoryEstimate.of("the decoded image", rasterBytesPerPixel * width * height)
                .plus("its heights", HEAP_BYTES_PER_PIXEL * width * height)
                .require(file + ": a " + width + " x " + height + " pixel image", "crop or scale it down");
    }
}
