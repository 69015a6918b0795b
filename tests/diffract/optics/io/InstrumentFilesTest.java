package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.optics.patches.Levelling;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Real files saved by the instruments (tests/fixtures/afm/README.md names where each comes from) read as Gwyddion
 * 2.62 reads them: the numbers below are Gwyddion's own, printed by the program in that README (it loads each file
 * with Gwyddion's file modules and prints every channel's title, units, size, minimum, maximum, mean and the
 * values at six places). Every value read here lies within 1e-6 (relative) of Gwyddion's; titles, units, sample
 * counts and extents are equal.
 */
class InstrumentFilesTest {
    static final Path DIR = Path.of("tests/fixtures/afm");

    /**
     * One channel as Gwyddion reads it: our index, title and unit, its size, its extent in metres, its minimum,
     * maximum and mean, and its values at (0, 0), (0, C-1), (R/3, C/5), (R/2, C/2), (R-1, 0), (R-1, C-1).
     */
    record Expected(String file, int index, String title, String unit, int cols, int rows, double widthM,
                    double heightM, double min, double max, double avg, double[] samples) {
        @Override
        public String toString() {
            return file + " channel " + index + " '" + title + "'";
        }
    }

    static Stream<Expected> channels() {
        return Stream.of(
            new Expected("di-3.di", 3, "Height", "m", 256, 256, 9.9999999999999991e-06, 9.9999999999999991e-06,
                    -1.0421134717685378e-06, 3.7236981626058954e-07, -2.8814328832868695e-07,
                    new double[] {3.6645366030130915e-07, -1.8740294023955838e-07, -4.1587096302000424e-08,
                        -2.75797270454689e-07, -1.6948046777467956e-07, -1.0088785956443449e-06}),
            new Expected("di-3.di", 0, "ZSensor", "m", 256, 256, 9.9999999999999991e-06, 9.9999999999999991e-06,
                    -6.4611431388381512e-07, 5.6401630244077993e-07, -1.6661202861000889e-08,
                    new double[] {5.6401630244077993e-07, 1.2714818378722784e-07, 1.7871877581281676e-07,
                        -1.3929987501164823e-08, 6.4315048675590771e-08, -6.1647604260474104e-07}),
            new Expected("sample_0.jpk", 1, "Height (retrace)", "m", 256, 256, 3.2691651420070083e-07,
                    3.2691651420070083e-07, 3.3031139584270314e-06, 3.3597597155885194e-06, 3.3453817636754692e-06,
                    new double[] {3.3031139584270314e-06, 3.3530883783199702e-06, 3.3414510578317422e-06,
                        3.3558850771786607e-06, 3.3351830024704627e-06, 3.3148224556405346e-06}),
            new Expected("sample_0.jpk", 2, "Height (measured) (retrace)", "m", 256, 256, 3.2691651420070083e-07,
                    3.2691651420070083e-07, 3.7833682754775202e-06, 3.8331853400435008e-06, 3.8200600484625325e-06,
                    new double[] {3.7833682754775202e-06, 3.8278230290109805e-06, 3.8169447838574601e-06,
                        3.8297005916474001e-06, 3.8097428279048605e-06, 3.7908305700237804e-06}),
            new Expected("sample_0.jpk", 5, "Error Signal (retrace)", "V", 256, 256, 3.2691651420070083e-07,
                    3.2691651420070083e-07, -0.010302428774447947, 0.008429020498996017, -0.00030597424017497212,
                    new double[] {-0.00014680611962842625, 0.00098868403799872947, 0.0020561321508578982,
                        0.00082474984105887169, -0.0016016163079621731, 0.0044430169843923117}),
            new Expected("Park_20210916_034.tiff", 0, "Topography", "m", 256, 256, 2.4999999999999998e-06,
                    2.4999999999999998e-06, -2.7132125971645411e-09, 9.2440945169534822e-09, -7.1463524990001127e-20,
                    new double[] {2.6494674597465676e-10, 3.6039948350847289e-10, 3.8859159240523375e-10,
                        -9.8338318097048363e-11, 1.8873186292704626e-10, 3.1793142302804805e-10}),
            new Expected("NanoSurf_20160301.nid", 0, "Z-Axis forward", "m", 128, 128, 1.0000000000000001e-05,
                    1.0000000000000001e-05, -2.9418945312499945e-07, -8.8500976562500417e-08, -1.4384254813194256e-07,
                    new double[] {-1.6784667968750015e-07, -9.7045898437500493e-08, -1.0070800781250077e-07,
                        -1.2420654296875055e-07, -1.7578124999999961e-07, -1.6693115234374923e-07}),
            new Expected("NanoSurf_20160301.nid", 1, "Amplitude forward", "V", 128, 128, 1.0000000000000001e-05,
                    1.0000000000000001e-05, 0.028533935546875, 0.076751708984375, 0.050586489960551262,
                    new double[] {0.047454833984375, 0.0494384765625, 0.0531768798828125, 0.0505828857421875,
                        0.0533294677734375, 0.049285888671875}),
            // Gwyddion numbers an NT-MDT file's channels from 0 and adds the frame's number to the title
            // ("1F:Iprobe (2)"); here a channel's index is its frame's and its title the frame's name
            new Expected("GaAs_map.mdt", 1, "1F:Iprobe", "A", 256, 256, 3.0008335441860447e-06,
                    3.0008335441860447e-06, -5.8746786559999992e-11, 5.2689382509439991e-08, 1.1146018657195286e-10,
                    new double[] {1.5258905599999997e-12, -1.7166268799999995e-11, -3.2425174399999998e-11,
                        -2.7466030079999993e-11, -2.8991920639999994e-11, -2.5558666879999997e-11}),
            new Expected("GaAs_map.mdt", 2, "1B:Iprobe", "A", 256, 256, 3.0008335441860447e-06,
                    3.0008335441860447e-06, -5.3558758655999988e-10, 5.0231935762559991e-08, 1.1868195562206179e-10,
                    new double[] {-1.602185088e-11, -1.3351542399999998e-11, -3.1280756479999995e-11,
                        7.0915763775999986e-10, -1.4495960319999997e-11, -2.5940139519999996e-11}));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("channels")
    void everyChannelReadsAsGwyddionReadsIt(Expected e) {
        ScanChannel c = HeightFieldReader.channels(DIR.resolve(e.file()), Reporter.SILENT).stream()
                .filter(ch -> ch.index() == e.index()).findFirst().orElseThrow();
        assertEquals(e.title(), c.title(), e + ": title");
        assertEquals(e.unit(), c.unit(), e + ": unit");
        assertEquals(e.cols(), c.cols(), e + ": columns");
        assertEquals(e.rows(), c.rows(), e + ": rows");
        assertClose(e.widthM() * 1e6, c.widthUm(), 1e-12, e + ": width");
        assertClose(e.heightM() * 1e6, c.heightExtentUm(), 1e-12, e + ": height");
        int r = e.rows();
        int k = e.cols();
        int[][] at = {{0, 0}, {0, k - 1}, {r / 3, k / 5}, {r / 2, k / 2}, {r - 1, 0}, {r - 1, k - 1}};
        for (int i = 0; i < at.length; i++) {
            assertClose(e.samples()[i], c.value(at[i][0], at[i][1]), 1e-6, e + ": value at " + at[i][0] + ", "
                    + at[i][1]);
        }
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        double sum = 0;
        for (int row = 0; row < r; row++) {
            for (int col = 0; col < k; col++) {
                double v = c.value(row, col);
                min = Math.min(min, v);
                max = Math.max(max, v);
                sum += v;
            }
        }
        assertClose(e.min(), min, 1e-6, e + ": minimum");
        assertClose(e.max(), max, 1e-6, e + ": maximum");
        // the mean of a levelled channel is ~0: compare it against the channel's range instead
        assertEquals(e.avg(), sum / (r * k), 1e-6 * (e.max() - e.min()), e + ": mean");
    }

    private static void assertClose(double expected, double actual, double relative, String what) {
        assertTrue(Math.abs(actual - expected) <= relative * Math.abs(expected), what + ": expected " + expected
                + ", read " + actual);
    }

    @Test
    void theDefaultChannelIsTheFilesHeightAndLoadsInMicrometres() {
        // di-3.di lists ZSensor (m) before Height (m): a channel titled Height comes first
        HeightField field = HeightFieldReader.load(DIR.resolve("di-3.di"), null, null, null, Levelling.NONE,
                Reporter.SILENT);
        assertEquals(256, field.cols());
        assertEquals(10.0 / 256, field.pixelSizeXUm(), 1e-12);
        // mean-subtracted: the maximum less the mean, in micrometres
        assertEquals((3.7236981626058954e-07 + 2.8814328832868695e-07) * 1e6, field.maxHeightUm(), 1e-9);
        HeightField nid = HeightFieldReader.load(DIR.resolve("NanoSurf_20160301.nid"), null, null, null,
                Levelling.NONE, Reporter.SILENT);
        assertEquals((-8.8500976562500417e-08 + 1.4384254813194256e-07) * 1e6, nid.maxHeightUm(), 1e-9);
    }

    @Test
    void aFileWithoutHeightsIsRefusedListingItsChannels() {
        UserInputException e = assertThrows(UserInputException.class, () -> HeightFieldReader.load(
                DIR.resolve("GaAs_map.mdt"), null, null, null, null, Reporter.SILENT));
        assertEquals(DIR.resolve("GaAs_map.mdt") + ": no channel holds heights (values in a length unit such as m);"
                + " channels: 1 '1F:Iprobe' (A, 256 x 256), 2 '1B:Iprobe' (A, 256 x 256); save the topography"
                + " channel with its unit from the microscope's software or Gwyddion", e.getMessage());
        UserInputException phase = assertThrows(UserInputException.class, () -> HeightFieldReader.load(
                DIR.resolve("sample_0.jpk"), null, null, "Lock-In Phase", null, Reporter.SILENT));
        assertTrue(phase.getMessage().contains("channel 9 'Lock-In Phase' is in deg, not a length"),
                phase.getMessage());
    }

    @Test
    void formatsAreFoundByContentWhateverTheName(@org.junit.jupiter.api.io.TempDir Path tmp) throws Exception {
        for (String[] f : new String[][] {{"di-3.di", "NANOSCOPE"}, {"sample_0.jpk", "JPK"},
                {"Park_20210916_034.tiff", "PARK"}, {"NanoSurf_20160301.nid", "NID"}, {"GaAs_map.mdt", "MDT"}}) {
            Path renamed = tmp.resolve("scan-" + f[1] + ".bin");
            Files.copy(DIR.resolve(f[0]), renamed);
            assertEquals(ScanFormat.valueOf(f[1]), HeightFieldReader.formatOf(renamed), f[0]);
            List<String> told = new java.util.ArrayList<>();
            Reporter collect = new Reporter() {
                @Override
                public void info(String message) {
                    told.add(message);
                }

                @Override
                public void warn(String message) {
                }

                @Override
                public void progress(String task, double fraction) {
                }
            };
            if (f[1].equals("JPK")) {
                // a 0.33 um scan: read, then refused as too narrow to diffract
                UserInputException narrow = assertThrows(UserInputException.class, () -> HeightFieldReader.load(
                        renamed, null, null, null, Levelling.NONE, collect));
                assertTrue(narrow.getMessage().contains("narrower than the shortest visible wavelength"),
                        narrow.getMessage());
            } else if (!f[1].equals("MDT")) {
                HeightFieldReader.load(renamed, null, null, null, Levelling.NONE, collect);
            }
            if (!f[1].equals("MDT")) {
                assertTrue(told.contains(renamed + ": read as " + ScanFormat.valueOf(f[1]).words()
                        + " (found by its content)"), told.toString());
            }
        }
        Path unknown = Files.write(tmp.resolve("mystery.bin"), new byte[] {1, 2, 3, 0, 9, 9});
        UserInputException e = assertThrows(UserInputException.class, () -> HeightFieldReader.load(unknown, null,
                0.1, Reporter.SILENT));
        assertEquals(unknown + ": not a height-field file diffract reads (its content matches none of them and"
                + " '.bin' is not their extension); read are: " + ScanFormat.listing(), e.getMessage());
    }
}
