package diffract.optics.io;

import diffract.util.UserInputException;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static diffract.optics.io.ReaderSupport.printable;

/**
 * JPK image scans (.jpk, the NanoWizard's own files, as Gwyddion's jpkscan module reads them): a TIFF whose first
 * directory holds a thumbnail and the scan's size in private tags (Grid-uLength 0x8042 and Grid-vLength 0x8043 in
 * metres, Grid-Reflect 0x8045), and each further directory one channel: 16- or 32-bit grey samples, its name
 * (ChannelFancyName 0x8052, else Channel 0x8050, and " (retrace)" when Channel-retrace 0x8051 is set) and its
 * calibration slots (NrOfSlots 0x8080, DefaultSlot 0x8081; slot n's name at 0x8090 + 0x30 n, its unit at
 * 0x80A2 + 0x30 n, its LinearScaling's multiplier and offset at 0x80A4 + 0x30 n and 0x80A5 + 0x30 n). A sample is
 * raw * multiplier + offset in the default slot's unit. The rows are stored from the bottom up unless Grid-Reflect
 * is set; row 0 of the channel is the top row, as Gwyddion shows it. A channel's index is its directory's.
 */
final class JpkReader {
    private static final int GRID_U_LENGTH = 0x8042;
    private static final int GRID_V_LENGTH = 0x8043;
    private static final int GRID_REFLECT = 0x8045;
    private static final int CHANNEL = 0x8050;
    private static final int CHANNEL_RETRACE = 0x8051;
    private static final int CHANNEL_FANCY_NAME = 0x8052;
    private static final int NR_OF_SLOTS = 0x8080;
    private static final int DEFAULT_SLOT = 0x8081;
    private static final int MAX_SLOTS = 64;

    private JpkReader() {
    }

    /** A TIFF whose first directory carries JPK's grid size. */
    static boolean looksLikeJpk(byte[] bytes) {
        if (!TiffDirectories.looksLikeTiff(bytes)) {
            return false;
        }
        try {
            TiffDirectories tiff = TiffDirectories.read(Path.of("probe"), bytes, "JPK");
            return tiff.has(0, GRID_U_LENGTH) && tiff.has(0, GRID_V_LENGTH);
        } catch (UserInputException e) {
            return false;
        }
    }

    static List<ScanChannel> channels(Path file, byte[] bytes) {
        TiffDirectories tiff = TiffDirectories.read(file, bytes, "JPK");
        Double u = tiff.real(0, GRID_U_LENGTH);
        Double v = tiff.real(0, GRID_V_LENGTH);
        if (u == null || v == null) {
            throw new UserInputException(file + ": a TIFF without JPK's grid size (tags 0x8042, 0x8043), so not a"
                    + " JPK scan; open the .jpk file the NanoWizard saved");
        }
        double width = Math.abs(u);
        double height = Math.abs(v);
        boolean reflect = tiff.integer(0, GRID_REFLECT, 0) != 0;
        List<ScanChannel> out = new ArrayList<>();
        for (int dir = 1; dir < tiff.count(); dir++) {
            String name = tiff.string(dir, CHANNEL_FANCY_NAME);
            if (name == null) {
                name = tiff.string(dir, CHANNEL);
            }
            int bits = (int) tiff.integer(dir, TiffDirectories.BITS_PER_SAMPLE, 0);
            long photometric = tiff.integer(dir, TiffDirectories.PHOTOMETRIC, -1);
            if (name == null || bits != 16 && bits != 32 || photometric != 0 && photometric != 1) {
                continue; // not a channel (Gwyddion skips these too)
            }
            String title = name + (tiff.integer(dir, CHANNEL_RETRACE, 0) != 0 ? " (retrace)" : "");
            String where = "JPK channel " + dir + " '" + printable(title) + "'";
            long slots = tiff.integer(dir, NR_OF_SLOTS, 0);
            String defaultSlot = tiff.string(dir, DEFAULT_SLOT);
            if (slots <= 0 || slots > MAX_SLOTS || defaultSlot == null) {
                throw new UserInputException(file + ": " + where + " has no calibration slots (NrOfSlots "
                        + slots + "); the file is damaged, save it from the JPK software again");
            }
            Double multiplier = null;
            Double offset = null;
            String unit = "";
            for (int n = 0; n < slots; n++) {
                if (!defaultSlot.equals(tiff.string(dir, 0x8090 + 0x30 * n))) {
                    continue;
                }
                String scaling = tiff.string(dir, 0x80A3 + 0x30 * n);
                if (scaling != null && !scaling.equals("LinearScaling")) {
                    throw new UserInputException(file + ": " + where + " is scaled by '" + printable(scaling)
                            + "', not LinearScaling, which is the only scaling read");
                }
                multiplier = tiff.real(dir, 0x80A4 + 0x30 * n);
                offset = tiff.real(dir, 0x80A5 + 0x30 * n);
                String slotUnit = tiff.string(dir, 0x80A2 + 0x30 * n);
                unit = slotUnit == null ? "" : slotUnit;
                break;
            }
            if (multiplier == null || offset == null || !Double.isFinite(multiplier) || !Double.isFinite(offset)) {
                throw new UserInputException(file + ": " + where + " has no linear scaling in its default slot '"
                        + printable(defaultSlot) + "'; the file is damaged, save it from the JPK software again");
            }
            int cols = (int) Math.min(Integer.MAX_VALUE, tiff.width(dir));
            int rows = (int) Math.min(Integer.MAX_VALUE, tiff.length(dir));
            double[] stored = tiff.samples(dir, where, multiplier, offset);
            double[] values = reflect ? stored : ReaderSupport.flippedRows(stored, cols, rows);
            out.add(new ScanChannel(dir, title, unit, cols, rows, "m", width, height, values, 0));
        }
        if (out.isEmpty()) {
            throw new UserInputException(file + ": the JPK file holds no channel (no 16- or 32-bit grey image with"
                    + " a channel name); open the scan's .jpk file");
        }
        return out;
    }
}
