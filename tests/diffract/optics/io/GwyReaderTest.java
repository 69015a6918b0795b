package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.patches.Levelling;
import diffract.optics.settings.Quantity;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

import static diffract.optics.io.GwyTestWriter.channel;
import static diffract.optics.io.GwyTestWriter.component;
import static diffract.optics.io.GwyTestWriter.container;
import static diffract.optics.io.GwyTestWriter.dataField;
import static diffract.optics.io.GwyTestWriter.doubles;
import static diffract.optics.io.GwyTestWriter.float64;
import static diffract.optics.io.GwyTestWriter.int32;
import static diffract.optics.io.GwyTestWriter.object;
import static diffract.optics.io.GwyTestWriter.objectComponent;
import static diffract.optics.io.GwyTestWriter.string;
import static diffract.optics.io.TestFiles.assertMeanSubtracted;
import static diffract.optics.io.TestFiles.assertUserError;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class GwyReaderTest {
    /** Written by the Python package gwyfile (tests/fixtures/write_gwy_fixtures.py): an independent writer. */
    static final Path GWYFILE_FIXTURE = Path.of("tests", "fixtures", "gwyfile-channels.gwy");

    @TempDir
    Path dir;

    private Path write(String name, byte[] bytes) throws IOException {
        Path file = dir.resolve(name);
        Files.write(file, bytes);
        return file;
    }

    private static HeightField load(Path file, String channel, Reporter reporter) {
        return HeightFieldReader.load(file, null, null, channel, Levelling.NONE, reporter);
    }

    /** The fixture's heights, (6 r + c) 10 nm on 6 x 4 samples, in micrometres. */
    private static double[] fixtureHeightsUm() {
        double[] h = new double[24];
        for (int r = 0; r < 4; r++) {
            for (int c = 0; c < 6; c++) {
                h[r * 6 + c] = (6 * r + c) * 1e-8 * 1e6;
            }
        }
        return h;
    }

    @Test
    void theIndependentWritersFileReadsTheFirstLengthChannelSkippingThePhase() {
        Reporter.Collecting reporter = new Reporter.Collecting();
        HeightField field = load(GWYFILE_FIXTURE, null, reporter);
        assertEquals(4, field.rows());
        assertEquals(6, field.cols());
        assertEquals(0.1, field.pixelSizeXUm(), 1e-15); // xreal 6e-7 m over 6 columns
        assertEquals(0.125, field.pixelSizeYUm(), 1e-15); // yreal 5e-7 m over 4 rows
        assertMeanSubtracted(fixtureHeightsUm(), field);
        assertTrue(reporter.infos().stream().anyMatch(m -> m.contains("channel 1 'Height' (m, 6 x 4), one of 4"
                + " (the first that holds heights)")), reporter.infos().toString());
    }

    @Test
    void theIndependentWritersChannelsByTitleIndexAndUnit() {
        List<ScanChannel> channels = HeightFieldReader.channels(GWYFILE_FIXTURE, Reporter.SILENT);
        assertEquals("0 'Phase' (deg, 6 x 4), 1 'Height' (m, 6 x 4), 2 'Topography nm' (nm, 6 x 4), 3 'Z' (m, 6 x 4)",
                ChannelChoice.listing(channels));
        assertEquals(0.6, channels.get(2).widthUm(), 1e-15); // xreal 0.6 in um
        assertEquals(0.5, channels.get(2).heightExtentUm(), 1e-15);

        // nanometres, by title and by title in another case: the same heights as channel 1
        assertMeanSubtracted(fixtureHeightsUm(), load(GWYFILE_FIXTURE, "Topography nm", Reporter.SILENT));
        assertMeanSubtracted(fixtureHeightsUm(), load(GWYFILE_FIXTURE, "topography NM", Reporter.SILENT));
        assertMeanSubtracted(fixtureHeightsUm(), load(GWYFILE_FIXTURE, "1", Reporter.SILENT));
        // by index: the one-letter title gwyfile stores as a character
        double[] z = new double[24];
        for (int i = 0; i < 24; i++) {
            z[i] = (5 - i % 6) * 2e-8 * 1e6;
        }
        assertMeanSubtracted(z, load(GWYFILE_FIXTURE, "3", Reporter.SILENT));
        assertMeanSubtracted(z, load(GWYFILE_FIXTURE, "Z", Reporter.SILENT));
    }

    @Test
    void aChannelThatIsNoLengthOrDoesNotExistIsRefusedWithTheList() {
        String list = "channels: 0 'Phase' (deg, 6 x 4), 1 'Height' (m, 6 x 4), 2 'Topography nm' (nm, 6 x 4),"
                + " 3 'Z' (m, 6 x 4)";
        String phase = assertUserError(GWYFILE_FIXTURE, () -> load(GWYFILE_FIXTURE, "Phase", Reporter.SILENT),
                "channel 0 'Phase' is in deg, not a length, so it holds no heights", list);
        assertUserError(GWYFILE_FIXTURE, () -> load(GWYFILE_FIXTURE, "Amplitude", Reporter.SILENT),
                "no channel 'Amplitude'", list, "give a title or an index of these");
        assertUserError(GWYFILE_FIXTURE, () -> load(GWYFILE_FIXTURE, "7", Reporter.SILENT), "no channel 7", list);
        InvalidSettingException e = assertThrows(InvalidSettingException.class,
                () -> load(GWYFILE_FIXTURE, "Phase", Reporter.SILENT));
        assertEquals(Quantity.CHANNEL, e.quantity(), phase);
    }

    @Test
    void withoutALengthChannelTheRefusalListsWhatTheFileHolds() throws IOException {
        double[] values = new double[16];
        Path file = write("signals.gwy", container(
                channel(0, "Phase", dataField(4, 4, 1e-6, 1e-6, "m", "deg", values)),
                channel(1, "Amplitude", dataField(4, 4, 1e-6, 1e-6, "m", "V", values)),
                channel(2, "Unknown", dataField(4, 4, 1e-6, 1e-6, "m", null, values))));
        assertUserError(file, () -> load(file, null, Reporter.SILENT),
                "no channel holds heights (values in a length unit such as m); channels: 0 'Phase' (deg, 4 x 4),"
                        + " 1 'Amplitude' (V, 4 x 4), 2 'Unknown' (no unit, 4 x 4)");
    }

    @ParameterizedTest(name = "z in {0}, x and y in {2}")
    @CsvSource({
        "m,  1e6,  m,  1e6",
        "um, 1,    nm, 1e-3",
        "nm, 1e-3, um, 1",
        "\u00B5m, 1, mm, 1e3",
        "pm, 1e-6, m,  1e6",
    })
    void unitsConvertToMicrometres(String zUnit, double zToUm, String xyUnit, double xyToUm) throws IOException {
        double[] values = {3, -1, 4, 1, -5, 9, 2, 6, 5, 3, 5, 8};
        double xReal = 0.8 / xyToUm; // 0.8 um over 4 columns, 0.6 um over 3 rows
        double yReal = 0.6 / xyToUm;
        Path file = write("units.gwy", container(channel(0, "Height", dataField(4, 3, xReal, yReal, xyUnit, zUnit,
                values))));
        HeightField field = load(file, null, Reporter.SILENT);
        assertEquals(0.2, field.pixelSizeXUm(), 1e-12);
        assertEquals(0.2, field.pixelSizeYUm(), 1e-12);
        double[] um = Arrays.stream(values).map(v -> v * zToUm).toArray();
        // row 0 is the first stored row, the top of Gwyddion's picture
        assertEquals(um[4] - TestFiles.mean(um), field.heightUm(1, 0), 1e-12 * Math.max(1, zToUm));
        for (int i = 0; i < um.length; i++) {
            assertEquals(um[i] - TestFiles.mean(um), field.heightUm(i / 4, i % 4), 1e-9 * zToUm);
        }
    }

    @Test
    void theGivenPixelSizeOverridesTheFilesAndStandsInForAMissingLateralUnit() throws IOException {
        double[] metres = new double[25];
        Arrays.setAll(metres, i -> i * 1e-9);
        Path noUnit = write("no-xy-unit.gwy", container(channel(0, "Height", dataField(5, 5, 1, 1, null, "m",
                metres))));
        InvalidSettingException e = assertThrows(InvalidSettingException.class,
                () -> load(noUnit, null, Reporter.SILENT));
        assertEquals(Quantity.PIXEL_SIZE, e.quantity());
        assertTrue(e.getMessage().contains("gives its lateral size in '', not a length"), e.getMessage());

        HeightField field = HeightFieldReader.load(noUnit, null, 0.09, null, Levelling.NONE, Reporter.SILENT);
        assertEquals(0.09, field.pixelSizeXUm());
        assertEquals(0.09, field.pixelSizeYUm());
    }

    @Test
    void missingSamplesAreCountedAndAMaskRefused() throws IOException {
        double[] metres = new double[36];
        Arrays.setAll(metres, i -> i * 1e-8);
        metres[7] = Double.NaN;
        metres[8] = Double.NaN;
        metres[30] = Double.POSITIVE_INFINITY;
        Path nan = write("nan.gwy", GwyTestWriter.heightsInMetres(6, 6, 1e-7, metres));
        assertUserError(nan, () -> load(nan, null, Reporter.SILENT), "channel 'Height' has 3 missing samples (NaN"
                + " or infinite), the first at row 1, column 1; fill them in Gwyddion (Data Process > Correct Data >"
                + " Remove Data Under Mask) or crop them");

        metres[7] = metres[8] = metres[30] = 0;
        double[] mask = new double[36];
        mask[3] = 1;
        mask[20] = 1;
        Path masked = write("masked.gwy", container(
                channel(0, "Height", dataField(6, 6, 6e-7, 6e-7, "m", "m", metres)),
                objectComponent("/0/mask", dataField(6, 6, 6e-7, 6e-7, "m", null, mask))));
        assertUserError(masked, () -> load(masked, null, Reporter.SILENT),
                "channel 'Height' has a mask over 2 samples", "Remove Data Under Mask", "Remove Mask");

        Path emptyMask = write("empty-mask.gwy", container(
                channel(0, "Height", dataField(6, 6, 6e-7, 6e-7, "m", "m", metres)),
                objectComponent("/0/mask", dataField(6, 6, 6e-7, 6e-7, "m", null, new double[36]))));
        assertEquals(36, load(emptyMask, null, Reporter.SILENT).sampleCount());
    }

    @Test
    void everyTruncationIsOneLineNamingTheFile() throws IOException {
        double[] metres = new double[25];
        Arrays.setAll(metres, i -> (i % 5) * 1e-8);
        byte[] good = GwyTestWriter.heightsInMetres(5, 5, 1e-7, metres);
        assertEquals(25, load(write("good.gwy", good), null, Reporter.SILENT).sampleCount());
        for (int length = 1; length < good.length; length++) {
            Path file = write("cut.gwy", Arrays.copyOf(good, length));
            String message = assertUserError(file, () -> load(file, null, Reporter.SILENT));
            assertTrue(length < 4 ? message.contains("not a Gwyddion file")
                    : message.contains("truncated or damaged .gwy"), length + ": " + message);
        }
        Path cut = write("cut-in-data.gwy", Arrays.copyOf(good, good.length - 100));
        assertUserError(cut, () -> load(cut, null, Reporter.SILENT), "truncated or damaged .gwy: GwyContainer at"
                + " byte 4 says it holds " + (good.length - 4 - "GwyContainer".length() - 5) + " bytes, but the file"
                + " ends after " + (good.length - 100 - 4 - "GwyContainer".length() - 5));
    }

    @Test
    void aWrongMagicIsRefused() throws IOException {
        byte[] good = GwyTestWriter.heightsInMetres(5, 5, 1e-7, new double[25]);
        byte[] other = good.clone();
        other[3] = 'Q';
        Path wrong = write("wrong.gwy", other);
        assertUserError(wrong, () -> load(wrong, null, Reporter.SILENT),
                "not a Gwyddion file (it must begin with GWYP)");
        other[3] = 'O';
        Path old = write("old.gwy", other);
        assertUserError(old, () -> load(old, null, Reporter.SILENT), "a Gwyddion 1 file (magic GWYO)");
        // the magic, not the name, decides
        Path renamed = write("scan.dat", good);
        assertEquals(25, load(renamed, null, Reporter.SILENT).sampleCount());
    }

    @Test
    void wrongComponentTypesAreNamed() throws IOException {
        double[] values = new double[16];
        byte[] xresAsDouble = object("GwyDataField", float64("xres", 4), int32("yres", 4), float64("xreal", 1e-6),
                float64("yreal", 1e-6), doubles("data", values));
        Path a = write("xres.gwy", container(channel(0, "Height", xresAsDouble)));
        assertUserError(a, () -> load(a, null, Reporter.SILENT), "'/0/data/xres' is of type 'd' (a double), expected"
                + " 'i' (a 32-bit integer); the file is damaged or not written by Gwyddion");

        Path b = write("data.gwy", container(objectComponent("/0/data", object("GwyDataField", int32("xres", 4),
                int32("yres", 4), float64("xreal", 1e-6), float64("yreal", 1e-6),
                component("data", 'I', new byte[4])))));
        assertUserError(b, () -> load(b, null, Reporter.SILENT), "'/0/data/data' is of type 'I' (32-bit integers),"
                + " expected 'D' (doubles)");

        Path c = write("field.gwy", container(string("/0/data", "not a field")));
        assertUserError(c, () -> load(c, null, Reporter.SILENT), "'/0/data' is of type 's' (a string), expected 'o'");

        Path d = write("kind.gwy", container(objectComponent("/0/data", object("GwyDataLine", int32("res", 4)))));
        assertUserError(d, () -> load(d, null, Reporter.SILENT), "'/0/data' is a GwyDataLine, expected a GwyDataField");

        Path e = write("title.gwy", container(objectComponent("/0/data", dataField(4, 4, 1e-6, 1e-6, "m", "m",
                values)), int32("/0/data/title", 5)));
        assertUserError(e, () -> load(e, null, Reporter.SILENT), "'/0/data/title' is of type 'i'");

        Path f = write("unknown.gwy", container(component("/0/data", 'z', new byte[8])));
        assertUserError(f, () -> load(f, null, Reporter.SILENT), "has the unknown type 'z'");

        Path g = write("count.gwy", container(channel(0, "Height", dataField(4, 4, 1e-6, 1e-6, "m", "m",
                new double[15]))));
        assertUserError(g, () -> load(g, null, Reporter.SILENT), "'/0/data' holds 15 values for xres x yres = 4 x 4");

        Path h = write("no-xreal.gwy", container(objectComponent("/0/data", object("GwyDataField", int32("xres", 4),
                int32("yres", 4), float64("yreal", 1e-6), doubles("data", values)))));
        assertUserError(h, () -> load(h, null, Reporter.SILENT), "'/0/data' lacks its 'xreal'");

        Path i = write("top.gwy", GwyTestWriter.file(object("GwyDataField", int32("xres", 4))));
        assertUserError(i, () -> load(i, null, Reporter.SILENT), "the top-level object is a GwyDataField, not the"
                + " GwyContainer");

        Path j = write("empty.gwy", container(string("/filename", "x.gwy")));
        assertUserError(j, () -> load(j, null, Reporter.SILENT), "the file holds no image");
    }

    @Test
    void anObjectLongerThanItsParentIsDamaged() throws IOException {
        byte[] file = container(channel(0, "Height", dataField(4, 4, 1e-6, 1e-6, "m", "m", new double[16])));
        // the lateral unit (a GwySIUnit inside the data field) claims 1000 bytes more than its 11
        int sizeAt = indexOf(file, "GwySIUnit".getBytes(java.nio.charset.StandardCharsets.US_ASCII)) + 10;
        java.nio.ByteBuffer.wrap(file).order(java.nio.ByteOrder.LITTLE_ENDIAN).putInt(sizeAt, 1011);
        Path damaged = write("long.gwy", file);
        assertUserError(damaged, () -> load(damaged, null, Reporter.SILENT), "truncated or damaged .gwy: GwySIUnit at"
                + " byte " + (sizeAt - 10) + " says it holds 1011 bytes, but its parent ends after");
    }

    private static int indexOf(byte[] haystack, byte[] needle) {
        outer:
        for (int i = 0; i + needle.length <= haystack.length; i++) {
            for (int j = 0; j < needle.length; j++) {
                if (haystack[i + j] != needle[j]) {
                    continue outer;
                }
            }
            return i;
        }
        throw new AssertionError("not found");
    }
}
