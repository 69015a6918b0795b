package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.optics.patches.Levelling;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import java.io.IOException;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

import static diffract.optics.io.TestFiles.assertUserError;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

class IbwReaderTest {
    private static final int COLS = 8;
    private static final int ROWS = 5;
    private static final String[] ASYLUM = {"HeightRetrace", "AmplitudeRetrace", "PhaseRetrace", "ZSensorRetrace"};

    @TempDir
    Path dir;

    private Path write(String name, byte[] bytes) throws IOException {
        Path file = dir.resolve(name);
        Files.write(file, bytes);
        return file;
    }

    private static HeightField load(Path file, String channel) {
        return HeightFieldReader.load(file, null, null, channel, Levelling.NONE, Reporter.SILENT);
    }

    /** Layer k's value at Igor's point (i, j), x = i fastest, j = 0 the bottom row: distinct in every layer. */
    private static double igorValue(int k, int i, int j) {
        return (i + 10 * j + 100 * k) * 1e-9 + (k == 2 ? 40 : 0); // layer 2, the phase, in degrees
    }

    /** Four Asylum layers, float32, 0.1 x 0.15 um per point, as an MFP-3D saves an image. */
    private static IbwTestWriter asylum(ByteOrder order) {
        double[] values = new double[COLS * ROWS * 4];
        for (int k = 0; k < 4; k++) {
            for (int j = 0; j < ROWS; j++) {
                for (int i = 0; i < COLS; i++) {
                    values[i + COLS * (j + ROWS * k)] = igorValue(k, i, j);
                }
            }
        }
        return IbwTestWriter.wave(COLS, ROWS, 4, values).order(order).step(1e-7, 1.5e-7, "m").dataUnits("m")
                .layers(ASYLUM).note("ScanSize: 8e-07\rScanRate: 1\r");
    }

    /** Layer k as the reader must give it: heights in um, row 0 the top of the picture (Igor's last row). */
    private static double[] expectedUm(int k) {
        double[] h = new double[COLS * ROWS];
        for (int r = 0; r < ROWS; r++) {
            for (int c = 0; c < COLS; c++) {
                h[r * COLS + c] = (float) igorValue(k, c, ROWS - 1 - r) * 1e6;
            }
        }
        return h;
    }

    private static void assertLayer(int k, HeightField field) {
        assertEquals(ROWS, field.rows());
        assertEquals(COLS, field.cols());
        assertEquals(0.1, field.pixelSizeXUm(), 1e-12);
        assertEquals(0.15, field.pixelSizeYUm(), 1e-12);
        double[] expected = expectedUm(k);
        double mean = TestFiles.mean(expected);
        for (int i = 0; i < expected.length; i++) {
            assertEquals(expected[i] - mean, field.heightUm(i / COLS, i % COLS), 1e-9, "layer " + k + ", sample " + i);
        }
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"little endian", "big endian"})
    void anAsylumImageReadsItsHeightLayerInEitherByteOrder(String endian) throws IOException {
        ByteOrder order = endian.startsWith("little") ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN;
        Path file = write("scan.ibw", asylum(order).bytes());
        assertLayer(0, load(file, null));
        assertLayer(3, load(file, "ZSensorRetrace"));
        assertLayer(3, load(file, "3"));
        assertLayer(1, load(file, "amplituderetrace"));
        List<ScanChannel> channels = HeightFieldReader.channels(file, Reporter.SILENT);
        assertEquals("0 'HeightRetrace' (m, 8 x 5), 1 'AmplitudeRetrace' (m, 8 x 5), 2 'PhaseRetrace' (deg, 8 x 5),"
                + " 3 'ZSensorRetrace' (m, 8 x 5)", ChannelChoice.listing(channels));
        assertEquals(0.8, channels.get(0).widthUm(), 1e-12);
        assertEquals(0.75, channels.get(0).heightExtentUm(), 1e-12);
    }

    @Test
    void bothByteOrdersGiveTheSameField() throws IOException {
        HeightField little = load(write("le.ibw", asylum(ByteOrder.LITTLE_ENDIAN).bytes()), null);
        HeightField big = load(write("be.ibw", asylum(ByteOrder.BIG_ENDIAN).bytes()), null);
        assertEquals(little.contentSha256(), big.contentSha256());
    }

    @Test
    void theHeightLayerIsTheDefaultWhereverItIs() throws IOException {
        // amplitude first: a length too, but the height layer is what an AFM user means
        String[] order = {"AmplitudeRetrace", "PhaseRetrace", "HeightRetrace", "ZSensorRetrace"};
        Path file = write("reordered.ibw", asylum(ByteOrder.LITTLE_ENDIAN).layers(order).bytes());
        assertLayer(2, load(file, null));
        assertTrue(ChannelChoice.byDefault(HeightFieldReader.channels(file, Reporter.SILENT)).orElseThrow()
                .title().equals("HeightRetrace"));
    }

    @Test
    void aPhaseLayerOrAnUnknownNameIsRefusedWithTheList() throws IOException {
        Path file = write("scan.ibw", asylum(ByteOrder.LITTLE_ENDIAN).bytes());
        String list = "channels: 0 'HeightRetrace' (m, 8 x 5), 1 'AmplitudeRetrace' (m, 8 x 5), 2 'PhaseRetrace'"
                + " (deg, 8 x 5), 3 'ZSensorRetrace' (m, 8 x 5)";
        assertUserError(file, () -> load(file, "PhaseRetrace"), "channel 2 'PhaseRetrace' is in deg, not a length",
                list);
        assertUserError(file, () -> load(file, "Height"), "no channel 'Height'", list);
        assertUserError(file, () -> load(file, "4"), "no channel 4", list);
    }

    @Test
    void theNoteNamesTheUnitOfALayer() throws IOException {
        double[] values = new double[COLS * ROWS * 2];
        Arrays.fill(values, 0, COLS * ROWS, 7);
        for (int i = 0; i < COLS * ROWS; i++) {
            values[COLS * ROWS + i] = i % COLS; // layer 1: 0..7 along x
        }
        IbwTestWriter wave = IbwTestWriter.wave(COLS, ROWS, 2, values).step(1e-7, 1e-7, "m")
                .layers("UserIn0Retrace", "UserCalcRetrace");
        // without a unit in the note or the name, a layer is in the wave's data unit: volts here, no heights
        Path volts = write("volts.ibw", wave.dataUnits("V").bytes());
        assertUserError(volts, () -> load(volts, null), "no channel holds heights",
                "0 'UserIn0Retrace' (V, 8 x 5), 1 'UserCalcRetrace' (V, 8 x 5)");
        // the note's "UserCalcUnit: nm" (the name without Retrace) makes layer 1 the heights, in nanometres
        Path nm = write("nm.ibw", wave.note("UserIn0Unit: V\rUserCalcUnit: nm\r").bytes());
        HeightField field = load(nm, null);
        for (int c = 0; c < COLS; c++) {
            assertEquals((c - 3.5) * 1e-3, field.heightUm(2, c), 1e-12);
        }
    }

    @Test
    void aTwoDimensionalIntegerWaveWithShortAndExtendedUnits() throws IOException {
        double[] counts = new double[6 * 4];
        for (int i = 0; i < counts.length; i++) {
            counts[i] = i * 3 - 30; // int16, in nanometres
        }
        IbwTestWriter wave = IbwTestWriter.wave(6, 4, 0, counts).type(IbwTestWriter.INT16).name("topo")
                .step(0.1, 0.2, "um").dataUnits("nm");
        Path file = write("topo.ibw", wave.bytes());
        HeightField field = load(file, null);
        assertEquals(0.1, field.pixelSizeXUm(), 1e-15);
        assertEquals(0.2, field.pixelSizeYUm(), 1e-15);
        // row 0 is Igor's last row: points 18..23
        assertEquals((18 * 3 - 30) * 1e-3 - (11.5 * 3 - 30) * 1e-3, field.heightUm(0, 0), 1e-12);
        assertEquals("0 'topo' (nm, 6 x 4)", ChannelChoice.listing(HeightFieldReader.channels(file, Reporter.SILENT)));

        // an extended data unit replaces the short one
        Path extended = write("extended.ibw", wave.dataUnits("").extendedDataUnits("\u00B5m").bytes());
        assertEquals((18 * 3 - 30) - (11.5 * 3 - 30), load(extended, null).heightUm(0, 0), 1e-12);
    }

    @Test
    void missingSamplesAreCounted() throws IOException {
        double[] values = new double[COLS * ROWS * 4];
        Arrays.fill(values, 1e-9);
        values[3] = Double.NaN; // Igor's bottom row, so the picture's last row
        values[COLS + 1] = Double.NaN;
        values[COLS * ROWS * 2] = Double.NaN; // in the phase layer, which is not read
        Path file = write("nan.ibw", IbwTestWriter.wave(COLS, ROWS, 4, values).order(ByteOrder.BIG_ENDIAN)
                .step(1e-7, 1e-7, "m").layers(ASYLUM).note("x: y").bytes());
        assertUserError(file, () -> load(file, null), "channel 'HeightRetrace' has 2 missing samples (NaN or"
                + " infinite), the first at row 3, column 1");
    }

    @Test
    void everyTruncationIsOneLineNamingTheFile() throws IOException {
        byte[] good = asylum(ByteOrder.LITTLE_ENDIAN).bytes();
        for (int length = 1; length < good.length; length++) {
            Path file = write("cut.ibw", Arrays.copyOf(good, length));
            String message = assertUserError(file, () -> load(file, null));
            assertTrue(message.contains("truncated Igor binary wave"), length + ": " + message);
        }
        Path data = write("data.ibw", Arrays.copyOf(good, 384 + 100));
        assertUserError(data, () -> load(data, null), "truncated Igor binary wave: 8 x 5 x 4 points of float32 need"
                + " 640 bytes after the headers, found 100");
        Path labels = write("labels.ibw", Arrays.copyOf(good, good.length - 1));
        assertUserError(labels, () -> load(labels, null), "the note, units and labels after the data need");
    }

    @Test
    void aWrongVersionOrChecksumIsRefused() throws IOException {
        byte[] good = asylum(ByteOrder.LITTLE_ENDIAN).bytes();
        byte[] seven = good.clone();
        seven[0] = 7;
        Path notIgor = write("seven.ibw", seven);
        assertUserError(notIgor, () -> load(notIgor, null), "not an Igor binary wave (its first two bytes, the"
                + " version, read as neither 1, 2, 3 nor 5");
        Path two = write("two.ibw", asylum(ByteOrder.LITTLE_ENDIAN).version(2).bytes());
        assertUserError(two, () -> load(two, null), "an Igor binary wave of version 2, which holds one-dimensional"
                + " waves only");
        byte[] flipped = good.clone();
        flipped[64 + 90] ^= 0x10; // inside sfA[0]
        Path checksum = write("checksum.ibw", flipped);
        assertUserError(checksum, () -> load(checksum, null), "the Igor header's checksum does not add up");
        // the content, not the name, decides
        assertEquals(COLS * ROWS, load(write("scan.dat", good), null).sampleCount());
    }

    @Test
    void wavesThatAreNoImageOfNumbersAreRefused() throws IOException {
        IbwTestWriter base = asylum(ByteOrder.LITTLE_ENDIAN);
        Path complex = write("complex.ibw", base.type(3).bytes());
        assertUserError(complex, () -> load(complex, null), "a complex wave (type 0x3)");
        Path text = write("text.ibw", asylum(ByteOrder.LITTLE_ENDIAN).type(0).bytes());
        assertUserError(text, () -> load(text, null), "a text wave");
        Path unknown = write("unknown.ibw", asylum(ByteOrder.LITTLE_ENDIAN).type(0x30).bytes());
        assertUserError(unknown, () -> load(unknown, null), "damaged Igor binary wave: the wave type 0x30");
        Path curve = write("curve.ibw", IbwTestWriter.wave(40, 0, 0, new double[40]).bytes());
        assertUserError(curve, () -> load(curve, null), "a one-dimensional wave (40 points");
        Path points = write("points.ibw", asylum(ByteOrder.LITTLE_ENDIAN).npnts(12).bytes());
        assertUserError(points, () -> load(points, null), "npnts = 12 does not match its dimensions 8 x 5 x 4");
    }
}
