package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;
import diffract.util.Reporter;
import diffract.util.UserInputException;

import java.nio.file.Path;
import java.util.OptionalDouble;

/**
 * One image of a multi-channel AFM file (a .gwy data field, a layer of an .ibw wave): its index and title, the
 * unit of its values, its size and lateral extent, and its values as stored (row-major from the top row of the
 * picture the microscope's software shows, in that unit). Only a channel in a length unit holds heights.
 */
public final class ScanChannel {
    private final int index;
    private final String title;
    private final String unit;
    private final int cols;
    private final int rows;
    private final String lateralUnit;
    private final double width;
    private final double height;
    private final double[] values;
    private final int maskedSamples;

    /**
     * @param index         what {@code channel} names it by: the N of a .gwy's "/N/data", an .ibw's layer
     * @param unit          the values' unit as the file spells it ("" when it has none)
     * @param lateralUnit   the unit of {@code width} and {@code height}
     * @param values        rows x cols values, row-major from the top, in {@code unit}; kept, not copied
     * @param maskedSamples samples under the file's mask of the channel (Gwyddion marks missing data with one)
     */
    ScanChannel(int index, String title, String unit, int cols, int rows, String lateralUnit, double width,
                double height, double[] values, int maskedSamples) {
        this.index = index;
        this.title = title.replaceAll("\\p{Cntrl}", "?"); // a title goes into one-line messages
        this.unit = unit.replaceAll("\\p{Cntrl}", "?");
        this.cols = cols;
        this.rows = rows;
        this.lateralUnit = lateralUnit.replaceAll("\\p{Cntrl}", "?");
        this.width = width;
        this.height = height;
        this.values = values;
        this.maskedSamples = maskedSamples;
    }

    public int index() {
        return index;
    }

    public String title() {
        return title;
    }

    /** The values' unit as the file spells it, "" when it has none. */
    public String unit() {
        return unit;
    }

    public int cols() {
        return cols;
    }

    public int rows() {
        return rows;
    }

    /** The value at row {@code row} (0 the top) and column {@code col}, in {@link #unit()}. */
    public double value(int row, int col) {
        return values[row * cols + col];
    }

    /** True when the values are lengths (m, nm, ...): a topography channel, not a phase, a current or a signal. */
    public boolean holdsHeights() {
        return LengthUnit.isLength(unit);
    }

    /** The extent along x (columns) in micrometres, NaN when the lateral unit is no length. */
    public double widthUm() {
        OptionalDouble factor = LengthUnit.micrometres(lateralUnit);
        return factor.isPresent() ? width * factor.getAsDouble() : Double.NaN;
    }

    /** The extent along y (rows) in micrometres, NaN when the lateral unit is no length. */
    public double heightExtentUm() {
        OptionalDouble factor = LengthUnit.micrometres(lateralUnit);
        return factor.isPresent() ? height * factor.getAsDouble() : Double.NaN;
    }

    /** "1 'Height' (m, 256 x 256)": index, title, unit, columns x rows. */
    public String summary() {
        return index + " '" + title + "' (" + (unit.isEmpty() ? "no unit" : unit) + ", " + cols + " x " + rows + ")";
    }

    /**
     * The channel as heights in micrometres: its values through its unit, the pixel sizes from its extent, or
     * {@code pixelSizeUm} when given.
     *
     * @throws UserInputException for missing samples (NaN, infinite or masked) and an unknown lateral unit
     */
    HeightField heightField(Path file, Double pixelSizeUm, Reporter reporter) {
        String name = "channel '" + title + "'";
        double toUm = LengthUnit.micrometres(unit).orElseThrow(() -> new IllegalStateException(
                "chosen channel " + summary() + " holds no heights"));
        ReaderSupport.requireHeap(file, values.length, name);
        double[] heightsUm = new double[values.length];
        int missing = 0;
        int firstMissing = -1;
        for (int i = 0; i < values.length; i++) {
            if (!Double.isFinite(values[i])) {
                if (missing++ == 0) {
                    firstMissing = i;
                }
            }
            heightsUm[i] = values[i] * toUm;
        }
        if (missing > 0) {
            throw new UserInputException(file + ": " + name + " has " + missing + " missing sample"
                    + (missing == 1 ? "" : "s") + " (NaN or infinite), the first at row " + firstMissing / cols
                    + ", column " + firstMissing % cols + "; " + ReaderSupport.FILL_MISSING);
        }
        if (maskedSamples > 0) {
            throw new UserInputException(file + ": " + name + " has a mask over " + maskedSamples + " sample"
                    + (maskedSamples == 1 ? "" : "s") + " (Gwyddion marks missing data with one); "
                    + ReaderSupport.FILL_MISSING + ", or remove the mask (Data Process > Mask > Remove Mask) if it"
                    + " marks something else");
        }
        double pixelXUm;
        double pixelYUm;
        double widthUm = widthUm();
        double heightUm = heightExtentUm();
        if (pixelSizeUm != null) {
            if (!Double.isNaN(widthUm)) {
                reporter.info(file + ": the given pixel size " + ReaderSupport.num(pixelSizeUm) + " um overrides the"
                        + " file's " + ReaderSupport.num(widthUm / cols) + " x " + ReaderSupport.num(heightUm / rows)
                        + " um");
            }
            pixelXUm = pixelSizeUm;
            pixelYUm = pixelSizeUm;
        } else {
            if (Double.isNaN(widthUm)) {
                throw new InvalidSettingException(Quantity.PIXEL_SIZE, file + ": " + name + " gives its lateral size in"
                        + " '" + lateralUnit + "', not a length, so the pixel size is unknown; give the pixel size in"
                        + " micrometres");
            }
            pixelXUm = widthUm / cols;
            pixelYUm = heightUm / rows;
            if (!(pixelXUm > 0) || !(pixelYUm > 0) || !Double.isFinite(pixelXUm) || !Double.isFinite(pixelYUm)) {
                throw new InvalidSettingException(Quantity.PIXEL_SIZE, file + ": " + name + " is "
                        + ReaderSupport.num(width) + " x " + ReaderSupport.num(height) + " " + lateralUnit
                        + ", not a positive size; fix the file or give the pixel size in micrometres");
            }
        }
        return ReaderSupport.build(file, rows, cols, heightsUm, pixelXUm, pixelYUm);
    }
}
