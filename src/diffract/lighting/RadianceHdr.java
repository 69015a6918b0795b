package diffract.lighting;

import diffract.util.UserInputException;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Radiance RGBE pictures ({@code .hdr}, G. Ward, "Real Pixels", Graphics Gems II, 1991; the format of Radiance's
 * {@code ra_*} tools and of light-probe collections): a text header ({@code #?RADIANCE} or {@code #?RGBE}, lines
 * such as {@code FORMAT=32-bit_rle_rgbe} and {@code EXPOSURE=e}, an empty line), the resolution line
 * {@code -Y height +X width} (rows from the top, pixels left to right, the only orientation read), then the pixels
 * as four bytes (R, G, B, shared exponent E): value = (byte + 0.5) 2^(E - 136), 0 when E = 0. Scanlines are flat,
 * old-style run-length encoded (a pixel (1, 1, 1, n) repeats the previous one n << shift times) or, for widths
 * 8..32767, new-style (2, 2, width high, width low, then each channel's runs: a count byte > 128 repeats the next
 * byte count - 128 times, else that many literal bytes follow). EXPOSURE values multiply into the stored pixels,
 * so pixels are divided by them. XYZE files are refused.
 */
public final class RadianceHdr {
    private RadianceHdr() {
    }

    public static LatLongMap read(Path file) {
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(file);
        } catch (IOException e) {
            throw new UserInputException("cannot read HDR environment " + file + ": " + e.getMessage());
        }
        try {
            return decode(bytes);
        } catch (IllegalArgumentException | ArrayIndexOutOfBoundsException e) {
            throw new UserInputException(file + ": not a readable Radiance .hdr picture: " + e.getMessage()
                    + " (write one with Radiance's ra_* tools, pfstools or GIMP)");
        }
    }

    /** Decodes a whole file's bytes. */
    static LatLongMap decode(byte[] bytes) {
        int[] at = {0};
        String first = line(bytes, at);
        if (!first.startsWith("#?")) {
            throw new IllegalArgumentException("it does not start with #?RADIANCE");
        }
        double exposure = 1;
        String headerLine;
        while (!(headerLine = line(bytes, at)).isEmpty()) {
            if (headerLine.startsWith("FORMAT=") && !headerLine.equals("FORMAT=32-bit_rle_rgbe")) {
                throw new IllegalArgumentException("format " + headerLine.substring(7) + "; only 32-bit_rle_rgbe is read");
            }
            if (headerLine.startsWith("EXPOSURE=")) {
                exposure *= Double.parseDouble(headerLine.substring(9).trim());
            }
        }
        String[] resolution = line(bytes, at).trim().split("\\s+");
        if (resolution.length != 4 || !resolution[0].equals("-Y") || !resolution[2].equals("+X")) {
            throw new IllegalArgumentException("resolution line '" + String.join(" ", resolution)
                    + "'; only the standard orientation -Y H +X W is read");
        }
        int height = Integer.parseInt(resolution[1]);
        int width = Integer.parseInt(resolution[3]);
        if (width < 2 || height < 1 || (long) width * height > 64L * 1024 * 1024) {
            throw new IllegalArgumentException("size " + width + " x " + height + " out of range");
        }
        float[] rgb = new float[3 * width * height];
        byte[] scanline = new byte[4 * width];
        for (int row = 0; row < height; row++) {
            readScanline(bytes, at, scanline, width);
            for (int c = 0; c < width; c++) {
                int e = scanline[4 * c + 3] & 0xFF;
                double f = e == 0 ? 0 : Math.scalb(1.0, e - 136) / exposure;
                for (int k = 0; k < 3; k++) {
                    rgb[3 * (row * width + c) + k] = e == 0 ? 0 : (float) (((scanline[4 * c + k] & 0xFF) + 0.5) * f);
                }
            }
        }
        return new LatLongMap(width, height, rgb);
    }

    private static String line(byte[] bytes, int[] at) {
        int start = at[0];
        while (at[0] < bytes.length && bytes[at[0]] != '\n') {
            at[0]++;
            if (at[0] - start > 4096) {
                throw new IllegalArgumentException("header line too long");
            }
        }
        if (at[0] >= bytes.length) {
            throw new IllegalArgumentException("header ends early");
        }
        String text = new String(bytes, start, at[0] - start, StandardCharsets.US_ASCII);
        at[0]++;
        return text;
    }

    private static void readScanline(byte[] b, int[] at, byte[] out, int width) {
        int p = at[0];
        if (width >= 8 && width <= 32767 && (b[p] & 0xFF) == 2 && (b[p + 1] & 0xFF) == 2
                && ((b[p + 2] & 0xFF) << 8 | (b[p + 3] & 0xFF)) == width) {
            p += 4;
            for (int channel = 0; channel < 4; channel++) {
                int x = 0;
                while (x < width) {
                    int count = b[p++] & 0xFF;
                    if (count > 128) {
                        count -= 128;
                        if (count > width - x) {
                            throw new IllegalArgumentException("a run passes the end of a scanline");
                        }
                        byte value = b[p++];
                        for (int i = 0; i < count; i++) {
                            out[4 * x++ + channel] = value;
                        }
                    } else {
                        if (count == 0 || count > width - x) {
                            throw new IllegalArgumentException("bad literal count " + count);
                        }
                        for (int i = 0; i < count; i++) {
                            out[4 * x++ + channel] = b[p++];
                        }
                    }
                }
            }
            at[0] = p;
            return;
        }
        // flat pixels, with old-style runs (1, 1, 1, n): repeat the previous pixel n << shift times
        int x = 0;
        int shift = 0;
        while (x < width) {
            int r = b[p] & 0xFF;
            int g = b[p + 1] & 0xFF;
            int bl = b[p + 2] & 0xFF;
            int e = b[p + 3] & 0xFF;
            p += 4;
            if (r == 1 && g == 1 && bl == 1 && x > 0) {
                int count = e << shift;
                if (count > width - x) {
                    throw new IllegalArgumentException("a run passes the end of a scanline");
                }
                for (int i = 0; i < count; i++) {
                    System.arraycopy(out, 4 * (x - 1), out, 4 * x, 4);
                    x++;
                }
                shift += 8;
            } else {
                out[4 * x] = (byte) r;
                out[4 * x + 1] = (byte) g;
                out[4 * x + 2] = (byte) bl;
                out[4 * x + 3] = (byte) e;
                x++;
                shift = 0;
            }
        }
        at[0] = p;
    }

    /** Writes a map as a Radiance picture, new-style run-length encoded when {@code runLength} (and 8 <= width). */
    public static void write(Path file, LatLongMap map, boolean runLength) throws IOException {
        try (OutputStream out = Files.newOutputStream(file)) {
            out.write(encode(map, runLength));
        }
    }

    static byte[] encode(LatLongMap map, boolean runLength) {
        int w = map.width();
        int h = map.height();
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        byte[] header = String.format(Locale.ROOT, "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n", h, w)
                .getBytes(StandardCharsets.US_ASCII);
        out.write(header, 0, header.length);
        byte[] scanline = new byte[4 * w];
        for (int r = 0; r < h; r++) {
            for (int c = 0; c < w; c++) {
                rgbe(map.get(c, r, 0), map.get(c, r, 1), map.get(c, r, 2), scanline, 4 * c);
            }
            if (runLength && w >= 8 && w <= 32767) {
                out.write(2);
                out.write(2);
                out.write(w >> 8);
                out.write(w & 0xFF);
                for (int channel = 0; channel < 4; channel++) {
                    encodeChannel(scanline, channel, w, out);
                }
            } else {
                out.write(scanline, 0, scanline.length);
            }
        }
        return out.toByteArray();
    }

    /** RGBE of a linear triple: the exponent of the largest channel shared by all three (Ward's float2rgbe). */
    static void rgbe(double r, double g, double b, byte[] out, int at) {
        double max = Math.max(r, Math.max(g, b));
        if (max < 1e-32) {
            out[at] = out[at + 1] = out[at + 2] = out[at + 3] = 0;
            return;
        }
        int exponent = Math.getExponent(max) + 1; // max = m 2^exponent with m in [0.5, 1)
        double scale = Math.scalb(256.0, -exponent);
        out[at] = (byte) Math.min(255, (int) (r * scale));
        out[at + 1] = (byte) Math.min(255, (int) (g * scale));
        out[at + 2] = (byte) Math.min(255, (int) (b * scale));
        out[at + 3] = (byte) (exponent + 128);
    }

    private static void encodeChannel(byte[] scanline, int channel, int w, ByteArrayOutputStream out) {
        int x = 0;
        while (x < w) {
            // a run of at least 4 equal bytes is worth a run code
            int run = 1;
            while (x + run < w && run < 127 && scanline[4 * (x + run) + channel] == scanline[4 * x + channel]) {
                run++;
            }
            if (run >= 4) {
                out.write(128 + run);
                out.write(scanline[4 * x + channel]);
                x += run;
                continue;
            }
            int start = x;
            int literal = 0;
            while (x < w && literal < 128) {
                int ahead = 1;
                while (x + ahead < w && ahead < 4 && scanline[4 * (x + ahead) + channel] == scanline[4 * x + channel]) {
                    ahead++;
                }
                if (ahead >= 4) {
                    break;
                }
                x++;
                literal++;
            }
            out.write(literal);
            for (int i = start; i < start + literal; i++) {
                out.write(scanline[4 * i + channel]);
            }
        }
    }
}
