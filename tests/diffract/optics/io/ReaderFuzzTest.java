package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Property-based fuzzing of the height-field readers: whatever bytes a file holds, loading it either
 * gives a valid field or a one-line {@link UserInputException}; no other exception escapes.
 */
class ReaderFuzzTest {

    @Property(tries = 300)
    void arbitraryBytesUnderEveryExtensionFailCleanly(@ForAll("extensions") String extension,
                                                      @ForAll("contents") byte[] content) throws Exception {
        loadExpectingOnlyUserErrors(content, extension);
    }

    @Property(tries = 200)
    void damagedGsfFilesFailCleanly(@ForAll @IntRange(min = 0, max = 40) int cut,
                                    @ForAll @IntRange(min = 0, max = 200) int flipAt,
                                    @ForAll @IntRange(min = 0, max = 255) int flipMask,
                                    @ForAll("headerLines") String extraHeader) throws Exception {
        byte[] good = gsf(8, 6, extraHeader);
        int length = Math.max(0, good.length - cut);
        byte[] damaged = java.util.Arrays.copyOf(good, length);
        if (flipAt < damaged.length) {
            damaged[flipAt] ^= (byte) flipMask;
        }
        loadExpectingOnlyUserErrors(damaged, ".gsf");
    }

    @Property(tries = 300)
    void damagedGwyFilesFailCleanly(@ForAll @IntRange(min = 0, max = 60) int cut,
                                    @ForAll @IntRange(min = 0, max = 700) int flipAt,
                                    @ForAll @IntRange(min = 0, max = 255) int flipMask) throws Exception {
        double[] metres = new double[48];
        java.util.Arrays.setAll(metres, i -> (i % 8) * 1e-8);
        byte[] good = GwyTestWriter.container(
                GwyTestWriter.channel(0, "Phase", GwyTestWriter.dataField(8, 6, 8e-7, 6e-7, "m", "deg", metres)),
                GwyTestWriter.channel(1, "Height", GwyTestWriter.dataField(8, 6, 8e-7, 6e-7, "m", "m", metres)));
        byte[] damaged = java.util.Arrays.copyOf(good, Math.max(0, good.length - cut));
        if (flipAt < damaged.length) {
            damaged[flipAt] ^= (byte) flipMask;
        }
        loadExpectingOnlyUserErrors(damaged, ".gwy");
    }

    /** Damage anywhere, the header's included: the checksum is made to add up again, so the reader goes on. */
    @Property(tries = 300)
    void damagedIbwFilesFailCleanly(@ForAll @IntRange(min = 0, max = 200) int cut,
                                    @ForAll @IntRange(min = 0, max = 1300) int flipAt,
                                    @ForAll @IntRange(min = 0, max = 255) int flipMask,
                                    @ForAll boolean bigEndian) throws Exception {
        double[] values = new double[8 * 6 * 2];
        java.util.Arrays.setAll(values, i -> (i % 8) * 1e-8);
        ByteOrder order = bigEndian ? ByteOrder.BIG_ENDIAN : ByteOrder.LITTLE_ENDIAN;
        byte[] good = IbwTestWriter.wave(8, 6, 2, values).order(order).step(1e-7, 1e-7, "m")
                .layers("HeightRetrace", "PhaseRetrace").note("ScanSize: 8e-07\r").bytes();
        byte[] damaged = java.util.Arrays.copyOf(good, Math.max(0, good.length - cut));
        if (flipAt < damaged.length) {
            damaged[flipAt] ^= (byte) flipMask;
            if (flipAt >= 4 && flipAt < 384 && damaged.length >= 384) {
                ByteBuffer header = ByteBuffer.wrap(damaged, 0, 384).order(order);
                header.putShort(2, (short) 0);
                int sum = 0;
                for (int i = 0; i < 384; i += 2) {
                    sum += header.getShort(i) & 0xFFFF;
                }
                header.putShort(2, (short) -sum);
            }
        }
        loadExpectingOnlyUserErrors(damaged, ".ibw");
    }

    @Property(tries = 200)
    void textMatricesWithJunkFailCleanly(@ForAll("matrixText") String text) throws Exception {
        loadExpectingOnlyUserErrors(text.getBytes(StandardCharsets.UTF_8), ".txt");
    }

    private static void loadExpectingOnlyUserErrors(byte[] content, String extension) throws Exception {
        Path file = Files.createTempFile("fuzz", extension);
        try {
            Files.write(file, content);
            HeightField field = HeightFieldReader.load(file, 0.5, 0.1, Reporter.SILENT);
            assertTrue(field.sampleCount() > 0);
        } catch (UserInputException e) {
            assertTrue(e.getMessage() != null && !e.getMessage().isBlank(), "empty message");
            assertTrue(e.getMessage().lines().count() == 1, "multi-line message: " + e.getMessage());
        } finally {
            Files.deleteIfExists(file);
        }
    }

    @Provide
    Arbitrary<String> extensions() {
        return Arbitraries.of(".png", ".bmp", ".tif", ".tiff", ".gsf", ".gwy", ".ibw", ".txt", ".csv", ".asc", ".dat",
                ".xyz", "");
    }

    @Provide
    Arbitrary<byte[]> contents() {
        Arbitrary<byte[]> random = Arbitraries.bytes().array(byte[].class).ofMaxSize(300);
        Arbitrary<byte[]> pngLike = random.map(tail -> concat(new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}, tail));
        Arbitrary<byte[]> gsfLike = random.map(tail -> concat("Gwyddion Simple Field 1.0\nXRes = 2\nYRes = 2\n"
                .getBytes(StandardCharsets.US_ASCII), tail));
        Arbitrary<byte[]> bmpLike = random.map(tail -> concat(new byte[] {'B', 'M'}, tail));
        Arbitrary<byte[]> gwyLike = random.map(tail -> concat("GWYPGwyContainer\0".getBytes(StandardCharsets.US_ASCII),
                tail));
        Arbitrary<byte[]> ibwLike = random.map(tail -> concat(new byte[] {5, 0}, tail));
        return Arbitraries.oneOf(random, pngLike, gsfLike, bmpLike, gwyLike, ibwLike);
    }

    @Provide
    Arbitrary<String> headerLines() {
        return Arbitraries.of("", "XReal = 1e-6\n", "XReal = -1\n", "ZUnits = nm\n", "ZUnits = V\n", "XRes = 0\n",
                "YRes = 99999999\n", "XYUnits = um\nXReal = 4\nYReal = 3\n", "junk line without equals\n");
    }

    @Provide
    Arbitrary<String> matrixText() {
        Arbitrary<String> token = Arbitraries.of("0", "1.5", "-2e-3", "NaN", "inf", "x", ",", ";", " ", "\t", "\n",
                "# c\n", "1e400", "0x10", "3,4", "");
        return token.list().ofMaxSize(40).map(list -> String.join(" ", list));
    }

    private static byte[] gsf(int xRes, int yRes, String extraHeader) {
        byte[] header = ("Gwyddion Simple Field 1.0\nXRes = " + xRes + "\nYRes = " + yRes
                + "\nXReal = 4e-7\nYReal = 3e-7\n" + extraHeader).getBytes(StandardCharsets.US_ASCII);
        int padding = 4 - header.length % 4;
        ByteBuffer buffer = ByteBuffer.allocate(header.length + padding + 4 * xRes * yRes).order(ByteOrder.LITTLE_ENDIAN);
        buffer.put(header).put(new byte[padding]);
        for (int i = 0; i < xRes * yRes; i++) {
            buffer.putFloat(i * 1e-8f);
        }
        return buffer.array();
    }

    private static byte[] concat(byte[] a, byte[] b) {
        byte[] out = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }
}
