package diffract.lighting;

import diffract.util.UserInputException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Radiance .hdr: written flat and run-length encoded, read back within RGBE's precision; bytes decoded by hand. */
class RadianceHdrTest {
    @TempDir
    Path dir;

    static LatLongMap ramp(int w, int h) {
        float[] rgb = new float[3 * w * h];
        for (int r = 0; r < h; r++) {
            for (int c = 0; c < w; c++) {
                int i = 3 * (r * w + c);
                rgb[i] = (float) (0.001 * Math.pow(10, 6.0 * c / w)); // six decades across a row
                rgb[i + 1] = c < w / 2 ? 0.25f : 3.0f;                 // long runs for the run-length code
                rgb[i + 2] = r == 0 && c == 1 ? 0 : (float) (0.5 + r);
            }
        }
        return new LatLongMap(w, h, rgb);
    }

    @Test
    void writtenPicturesReadBackWithinRgbePrecision() throws Exception {
        LatLongMap map = ramp(40, 6);
        for (boolean runLength : new boolean[] {false, true}) {
            Path file = dir.resolve("ramp-" + runLength + ".hdr");
            RadianceHdr.write(file, map, runLength);
            LatLongMap back = RadianceHdr.read(file);
            assertEquals(40, back.width());
            assertEquals(6, back.height());
            for (int r = 0; r < 6; r++) {
                for (int c = 0; c < 40; c++) {
                    double max = Math.max(map.get(c, r, 0), Math.max(map.get(c, r, 1), map.get(c, r, 2)));
                    for (int k = 0; k < 3; k++) {
                        // 8 bits of mantissa shared by the three channels: an error of at most 1/256 of the largest
                        assertEquals(map.get(c, r, k), back.get(c, r, k), max / 256 + 1e-30,
                                "pixel " + c + "," + r + " channel " + k + " rle " + runLength);
                    }
                }
            }
        }
        long flat = Files.size(dir.resolve("ramp-false.hdr"));
        long rle = Files.size(dir.resolve("ramp-true.hdr"));
        assertTrue(rle < flat, "run-length encoding shrinks a picture with runs: " + rle + " vs " + flat);
    }

    @Test
    void handMadeBytesDecodeToTheFormatsValues() throws Exception {
        // 2 x 1, flat: (128, 64, 0, 129) = (128.5, 64.5, 0.5) 2^(129-136); an old-style run repeats it once
        byte[] header = "#?RADIANCE\nEXPOSURE=2\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 3\n".getBytes(StandardCharsets.US_ASCII);
        byte[] pixels = {(byte) 128, 64, 0, (byte) 129, 1, 1, 1, 2};
        byte[] file = new byte[header.length + pixels.length];
        System.arraycopy(header, 0, file, 0, header.length);
        System.arraycopy(pixels, 0, file, header.length, pixels.length);
        LatLongMap map = RadianceHdr.decode(file);
        double unit = Math.scalb(1.0, 129 - 136) / 2; // EXPOSURE=2 divides
        for (int c = 0; c < 3; c++) {
            assertEquals(128.5 * unit, map.get(c, 0, 0), 1e-7);
            assertEquals(64.5 * unit, map.get(c, 0, 1), 1e-7);
            assertEquals(0.5 * unit, map.get(c, 0, 2), 1e-7);
        }
    }

    @Test
    void otherFilesAreRefusedInOneLine() throws Exception {
        Path png = dir.resolve("not.hdr");
        Files.write(png, new byte[] {(byte) 0x89, 'P', 'N', 'G', '\n', 0, 0});
        UserInputException e = assertThrows(UserInputException.class, () -> RadianceHdr.read(png));
        assertTrue(e.getMessage().contains("not.hdr") && !e.getMessage().contains("\n"), e.getMessage());
        Path xyz = dir.resolve("xyz.hdr");
        Files.write(xyz, "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 2\n\0\0\0\0\0\0\0\0".getBytes(StandardCharsets.US_ASCII));
        e = assertThrows(UserInputException.class, () -> RadianceHdr.read(xyz));
        assertTrue(e.getMessage().contains("xyze"), e.getMessage());
    }
}
