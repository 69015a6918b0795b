package diffract.optics.io;

import diffract.util.Reporter;
import diffract.util.UserInputException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.zip.CRC32;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A header that declares more samples than the file holds or the heap takes is refused from the header, before
 * anything of that size is allocated or decoded: a PNG of 40000 x 40000 pixels (whose decoding would run for
 * seconds and exhaust the heap), a .gsf of 200000 x 200000 samples, a NanoScope image and a Nanosurf channel that
 * claim more samples than their files hold.
 */
class DeclaredSizeTest {
    @TempDir
    Path dir;

    @Test
    void aHugePngIsRefusedFromItsHeader() throws IOException {
        Path png = Files.write(dir.resolve("huge.png"), png(40000, 40000));
        UserInputException e = assertThrows(UserInputException.class, () -> HeightFieldReader.load(png, 1.0, 0.1,
                Reporter.SILENT));
        assertTrue(e.getMessage().startsWith(png + ": the image of 1600000000 samples needs about"), e.getMessage());
        Path wider = Files.write(dir.resolve("wider.png"), png(100000, 100000));
        e = assertThrows(UserInputException.class, () -> HeightFieldReader.load(wider, 1.0, 0.1, Reporter.SILENT));
        assertTrue(e.getMessage().contains("claims 100000 x 100000 samples, more than one array holds"),
                e.getMessage());
    }

    @Test
    void headersClaimingMoreThanTheFileAreRefused() throws IOException {
        Path gsf = Files.write(dir.resolve("big.gsf"), ("Gwyddion Simple Field 1.0\nXRes = 200000\nYRes = 200000\n"
                + "XReal = 1e-5\nYReal = 1e-5\n\0\0").getBytes(StandardCharsets.US_ASCII));
        UserInputException e = assertThrows(UserInputException.class, () -> HeightFieldReader.load(gsf, null, null,
                Reporter.SILENT));
        assertTrue(e.getMessage().contains("200000 x 200000"), e.getMessage());

        byte[] nid = Files.readAllBytes(InstrumentFilesTest.DIR.resolve("NanoSurf_20160301.nid"));
        String text = new String(nid, StandardCharsets.ISO_8859_1).replaceFirst("Points=128\r?\nLines=128",
                "Points=128\r\nLines=99999");
        Path bigNid = Files.write(dir.resolve("big.nid"), text.getBytes(StandardCharsets.ISO_8859_1));
        e = assertThrows(UserInputException.class, () -> HeightFieldReader.channels(bigNid, Reporter.SILENT));
        assertTrue(e.getMessage().contains("claims 128 x 99999 samples of 2 bytes"), e.getMessage());

        byte[] spm = Files.readAllBytes(InstrumentFilesTest.DIR.resolve("di-3.di"));
        String header = new String(spm, StandardCharsets.ISO_8859_1).replaceAll("\\\\Samps/line: 256",
                "\\\\Samps/line: 9999");
        Path bigSpm = Files.write(dir.resolve("big.spm"), header.getBytes(StandardCharsets.ISO_8859_1));
        e = assertThrows(UserInputException.class, () -> HeightFieldReader.channels(bigSpm, Reporter.SILENT));
        assertTrue(e.getMessage().contains("9999"), e.getMessage());
    }

    /** A PNG's signature, IHDR of an 8-bit grey image of this size, and IEND: all a decoder needs to allocate. */
    static byte[] png(int width, int height) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.write(new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'});
        ByteBuffer ihdr = ByteBuffer.allocate(13).putInt(width).putInt(height).put((byte) 8).put((byte) 0)
                .put((byte) 0).put((byte) 0).put((byte) 0);
        chunk(out, "IHDR", ihdr.array());
        chunk(out, "IEND", new byte[0]);
        return out.toByteArray();
    }

    private static void chunk(ByteArrayOutputStream out, String type, byte[] data) throws IOException {
        out.write(ByteBuffer.allocate(4).putInt(data.length).array());
        byte[] t = type.getBytes(StandardCharsets.US_ASCII);
        out.write(t);
        out.write(data);
        CRC32 crc = new CRC32();
        crc.update(t);
        crc.update(data);
        out.write(ByteBuffer.allocate(4).putInt((int) crc.getValue()).array());
    }
}
