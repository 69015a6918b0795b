package diffract.util;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.io.BufferedOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

/**
 * Writes images: 8-bit PNG from display-encoded values in [0, 1], and PFM (Portable Float Map) with the raw
 * floats. Pixels are row-major from the top-left, {@code channels} (1 or 3) interleaved floats per pixel.
 * Files are written to a temporary sibling and renamed, so a crash never leaves half an image.
 */
public final class ImageFiles {
    private ImageFiles() {
    }

    /** PNG of values already encoded for display (e.g. sRGB-encoded); clamped to [0, 1], NaN written as 0. */
    public static void writePng(Path file, float[] pixels, int width, int height, int channels) throws IOException {
        checkSize(pixels, width, height, channels);
        BufferedImage image = new BufferedImage(width, height,
                channels == 1 ? BufferedImage.TYPE_BYTE_GRAY : BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int i = (y * width + x) * channels;
                if (channels == 1) {
                    image.getRaster().setSample(x, y, 0, toByte(pixels[i]));
                } else {
                    int rgb = (toByte(pixels[i]) << 16) | (toByte(pixels[i + 1]) << 8) | toByte(pixels[i + 2]);
                    image.setRGB(x, y, rgb);
                }
            }
        }
        writeAtomically(file, out -> {
            if (!ImageIO.write(image, "png", out)) {
                throw new IOException("no PNG writer in this Java runtime");
            }
        });
    }

    /**
     * PFM: header "PF" (colour) or "Pf" (grey), width height, scale -1 (little-endian), then rows from the
     * bottom up as the format requires.
     */
    public static void writePfm(Path file, float[] pixels, int width, int height, int channels) throws IOException {
        checkSize(pixels, width, height, channels);
        writeAtomically(file, raw -> {
            DataOutputStream out = new DataOutputStream(new BufferedOutputStream(raw));
            out.writeBytes((channels == 3 ? "PF" : "Pf") + "\n" + width + " " + height + "\n-1.0\n");
            ByteBuffer row = ByteBuffer.allocate(width * channels * 4).order(ByteOrder.LITTLE_ENDIAN);
            for (int y = height - 1; y >= 0; y--) {
                row.clear();
                for (int i = 0; i < width * channels; i++) {
                    row.putFloat(pixels[y * width * channels + i]);
                }
                out.write(row.array());
            }
            out.flush();
        });
    }

    /**
     * Reads a PFM written by {@link #writePfm}; returns top-down row-major floats.
     *
     * @throws IOException naming what is wrong when the file is no PFM (another image, truncated, a bad header)
     */
    public static float[] readPfm(Path file, int[] widthHeightChannels) throws IOException {
        byte[] bytes = Files.readAllBytes(file);
        int[] pos = {0};
        String magic = token(bytes, pos);
        if (!magic.equals("PF") && !magic.equals("Pf")) {
            String kind = bytes.length >= 4 && bytes[1] == 'P' && bytes[2] == 'N' && bytes[3] == 'G' ? " (it is a PNG)"
                    : "";
            throw new IOException("not a PFM file: it does not start with PF or Pf" + kind);
        }
        int channels = magic.equals("PF") ? 3 : 1;
        int width = positiveInt(token(bytes, pos), "width");
        int height = positiveInt(token(bytes, pos), "height");
        String scaleText = token(bytes, pos);
        double scale;
        try {
            scale = Double.parseDouble(scaleText);
        } catch (NumberFormatException e) {
            throw new IOException("bad PFM header: the scale '" + scaleText + "' is not a number");
        }
        if (scale == 0 || !Double.isFinite(scale)) {
            throw new IOException("bad PFM header: the scale must be a non-zero number, got " + scaleText);
        }
        int start = pos[0] + 1; // the single whitespace after the scale
        long needed = 4L * width * height * channels;
        if (needed > Integer.MAX_VALUE - 8 || bytes.length - (long) start < needed) {
            throw new IOException(String.format(java.util.Locale.ROOT, "truncated PFM: %d x %d x %d floats need %d"
                    + " bytes after the header, the file has %d", width, height, channels, needed,
                    Math.max(0, bytes.length - start)));
        }
        ByteOrder order = scale < 0 ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN;
        ByteBuffer data = ByteBuffer.wrap(bytes, start, bytes.length - start).order(order);
        float[] pixels = new float[width * height * channels];
        for (int y = height - 1; y >= 0; y--) {
            for (int i = 0; i < width * channels; i++) {
                pixels[y * width * channels + i] = data.getFloat();
            }
        }
        widthHeightChannels[0] = width;
        widthHeightChannels[1] = height;
        widthHeightChannels[2] = channels;
        return pixels;
    }

    /** The next whitespace-separated ASCII token of a PFM header (at most 32 characters). */
    private static String token(byte[] bytes, int[] pos) throws IOException {
        int p = pos[0];
        while (p < bytes.length && Character.isWhitespace(bytes[p])) {
            p++;
        }
        int start = p;
        while (p < bytes.length && !Character.isWhitespace(bytes[p]) && p - start < 32) {
            p++;
        }
        if (p == start) {
            throw new IOException("not a PFM file: its header ends early");
        }
        pos[0] = p;
        return new String(bytes, start, p - start, java.nio.charset.StandardCharsets.ISO_8859_1);
    }

    private static int positiveInt(String text, String what) throws IOException {
        try {
            int value = Integer.parseInt(text);
            if (value > 0) {
                return value;
            }
        } catch (NumberFormatException e) {
            // falls through to the message below
        }
        throw new IOException("bad PFM header: the " + what + " must be a positive whole number, got '" + text + "'");
    }

    private static int toByte(float v) {
        if (!(v > 0)) {
            return 0;
        }
        return Math.min(255, Math.round(v * 255f));
    }

    private static void checkSize(float[] pixels, int width, int height, int channels) {
        if (channels != 1 && channels != 3) {
            throw new IllegalArgumentException("channels must be 1 or 3, got " + channels);
        }
        if (pixels.length != width * height * channels) {
            throw new IllegalArgumentException("expected " + width * height * channels + " values, got " + pixels.length);
        }
    }

    /** Something that writes a whole file to a stream. */
    public interface StreamWriter {
        void write(OutputStream out) throws IOException;
    }

    /**
     * Writes to {@code file.tmp-<pid>-<nanos>} in the same folder, then renames it over {@code file}. What exists at
     * {@code file} and is not a regular file (a device, a pipe, a socket, a folder) is never replaced: a rename would
     * swap a device node for a picture. Failures name {@code file}, not the temporary name.
     */
    public static void writeAtomically(Path file, StreamWriter writer) throws IOException {
        Path absolute = file.toAbsolutePath();
        refuseToReplaceSpecial(file, absolute);
        Path dir = absolute.getParent();
        Path tmp = absolute.resolveSibling(absolute.getFileName() + FolderLock.TEMPORARY_MARK
                + ProcessHandle.current().pid() + "-" + System.nanoTime());
        try {
            if (dir != null) {
                Files.createDirectories(dir);
            }
            try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(tmp))) {
                writer.write(out);
            }
            refuseToReplaceSpecial(file, absolute); // something may have appeared there while we wrote
            Files.move(tmp, absolute, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } catch (FileSystemException e) {
            throw namingTarget(e, file, tmp);
        } finally {
            removeQuietly(tmp);
        }
    }

    /** A temporary file's cleanup never hides the failure that left it (or found no folder to make it in). */
    private static void removeQuietly(Path tmp) {
        try {
            Files.deleteIfExists(tmp);
        } catch (IOException e) {
            // the failure being thrown, if any, says what went wrong; a leftover carries the temporary mark
        }
    }

    private static void refuseToReplaceSpecial(Path file, Path absolute) throws FileSystemException {
        if (Files.exists(absolute) && !Files.isRegularFile(absolute)) {
            throw new FileSystemException(file.toString(), null, "it is " + OutputPaths.kind(absolute)
                    + ", not a regular file, and is left as it is");
        }
    }

    /** The same failure, naming the file the user asked for where it named the temporary one. */
    private static FileSystemException namingTarget(FileSystemException e, Path file, Path tmp) {
        if (!tmp.toString().equals(e.getFile())) {
            return e;
        }
        FileSystemException named = e instanceof AccessDeniedException ? new AccessDeniedException(file.toString())
                : e instanceof NoSuchFileException ? new NoSuchFileException(file.toString())
                : new FileSystemException(file.toString(), null, e.getReason());
        named.initCause(e);
        return named;
    }
}
