package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.patches.Levelling;
import diffract.optics.settings.Quantity;
import diffract.optics.settings.SpectralSettings;
import diffract.util.Reporter;
import diffract.util.UserInputException;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * Loads a nanostructure height field from a file, levels it and returns it mean-subtracted, as the thesis'
 * precompute uses it. Formats, chosen by content (PNG, BMP, TIFF, GSF, GWY and Igor signatures) and otherwise by
 * extension (docs/guide/formats.md describes each):
 * <ul>
 *   <li>grey images (.png, .bmp, .tif, .tiff; 8 or 16 bits, colour via luminance): grey 0..max maps linearly
 *       to 0..{@code maxHeightUm}; needs {@code maxHeightUm} and {@code pixelSizeUm};</li>
 *   <li>text matrices (.txt, .csv, .asc, .dat): heights in micrometres, one row per line; needs
 *       {@code pixelSizeUm};</li>
 *   <li>Gwyddion Simple Field (.gsf): heights and pixel sizes from the file (metres by default), converted to
 *       micrometres; {@code pixelSizeUm}, if given, overrides the file's;</li>
 *   <li>Gwyddion files (.gwy) and Igor binary waves (.ibw, Asylum Research AFMs): one of their channels (by
 *       default the first in a length unit, {@link ChannelChoice}), heights and pixel sizes from the file as for
 *       .gsf.</li>
 * </ul>
 * For every format but images a given {@code maxHeightUm} rescales the levelled heights so that max - min equals
 * it. A scan with fewer than 2 samples along an axis, or narrower than the shortest visible wavelength, is refused:
 * it diffracts nothing. Every problem with the input is a one-line {@link UserInputException} naming the file;
 * implausible values (a pixel size or height that looks like it is in the wrong unit, a flat field) are warnings on
 * the {@link Reporter}.
 */
public final class HeightFieldReader {
    /** Plausible lateral sampling of an AFM patch: 1 nm to 10 um per pixel. */
    static final double MIN_PLAUSIBLE_PIXEL_UM = 0.001;
    static final double MAX_PLAUSIBLE_PIXEL_UM = 10.0;
    /** Plausible peak-to-valley height of a diffracting nanostructure: 1 nm to 20 um. */
    static final double MIN_PLAUSIBLE_HEIGHT_UM = 0.001;
    static final double MAX_PLAUSIBLE_HEIGHT_UM = 20.0;
    /**
     * The shortest wavelength of the visible band: a scan narrower than it has its first diffraction order
     * (sin theta = lambda / width) beyond the horizon for light from above.
     */
    static final double MIN_EXTENT_UM = SpectralSettings.LAMBDA_MIN_NM / 1000.0;

    /** Every format read, for messages. */
    static final String SUPPORTED = ScanFormat.listing();

    private HeightFieldReader() {
    }

    /**
     * The heights as read (no levelling; the default channel of a multi-channel file), mean-subtracted: what a
     * reader's own tests compare with the file's numbers.
     *
     * @see #load(Path, Double, Double, String, Levelling, Reporter)
     */
    public static HeightField load(Path file, Double maxHeightUm, Double pixelSizeUm, Reporter reporter) {
        return load(file, maxHeightUm, pixelSizeUm, null, Levelling.NONE, reporter);
    }

    /**
     * @param file        the height-field file
     * @param maxHeightUm the height of the brightest grey value (images, required), or the peak-to-valley height
     *                    to rescale to (every other format, optional); null when not given
     * @param pixelSizeUm the sample spacing in micrometres (images and text, required; .gsf, .gwy, .ibw: optional
     *                    override); null when not given
     * @param channel     a multi-channel file's channel, by title or index; null for the default
     * @param levelling   what is removed before use; null for the format's default ({@link Levelling#defaultFor}:
     *                    a plane for .gwy and .ibw, nothing for exports)
     * @param reporter    receives plausibility warnings and notes
     * @return the levelled field with its mean subtracted
     * @throws UserInputException for any problem with the file or the options
     */
    public static HeightField load(Path file, Double maxHeightUm, Double pixelSizeUm, String channel,
                                   Levelling levelling, Reporter reporter) {
        checkOption(file, Quantity.MAX_HEIGHT, maxHeightUm,
                "the peak-to-valley height of the structure in micrometres");
        checkOption(file, Quantity.PIXEL_SIZE, pixelSizeUm, "the sample spacing in micrometres");
        return read(file, readBytes(file), maxHeightUm, pixelSizeUm, channel, levelling, reporter);
    }

    /**
     * As {@link #load(Path, Double, Double, String, Levelling, Reporter)} for a file's content already in memory.
     *
     * @param file    the file's name, for messages and the extension
     * @param content the file's bytes
     */
    public static HeightField read(Path file, byte[] content, Double maxHeightUm, Double pixelSizeUm, String channel,
                                   Levelling levelling, Reporter reporter) {
        checkOption(file, Quantity.MAX_HEIGHT, maxHeightUm,
                "the peak-to-valley height of the structure in micrometres");
        checkOption(file, Quantity.PIXEL_SIZE, pixelSizeUm, "the sample spacing in micrometres");
        byte[] bytes = content;
        if (bytes.length == 0) {
            throw new UserInputException(file + ": the file is empty (0 bytes); export the height field again");
        }
        ScanFormat format = ScanFormat.detect(file, bytes);
        nameIfUnexpected(file, format, reporter);
        if (channel != null && !format.hasChannels()) {
            throw new InvalidSettingException(Quantity.CHANNEL, file + ": " + format.words() + " holds one height"
                    + " field, no channels to choose from (only the instruments' files have channels); leave the"
                    + " channel out");
        }

        HeightField raw;
        switch (format) {
            case IMAGE:
                requireImageOptions(file, maxHeightUm, pixelSizeUm);
                ImageHeader.requireDecodable(file, bytes);
                raw = ImageHeightFieldReader.read(file, bytes, maxHeightUm, pixelSizeUm, reporter);
                break;
            case TEXT:
                if (pixelSizeUm == null) {
                    throw new InvalidSettingException(Quantity.PIXEL_SIZE, file + ": a text matrix carries no pixel"
                            + " size; give the pixel size (the sample spacing in micrometres)");
                }
                raw = TextMatrixReader.read(file, bytes, pixelSizeUm);
                break;
            case GSF:
                raw = GsfReader.read(file, bytes, pixelSizeUm, reporter);
                break;
            default:
                raw = ChannelChoice.choose(file, channels(file, format, bytes, reporter), channel, reporter)
                        .heightField(file, pixelSizeUm, reporter);
                break;
        }

        // the warning first: a pixel size in the wrong unit is the likely reason for a scan too small to use
        warnAboutPixelSize(file, format, raw, pixelSizeUm, reporter);
        requireResolvingSize(file, raw);
        if (maxHeightUm != null) {
            ReaderSupport.warnIfImplausible(file, "maximum height", maxHeightUm, "", MIN_PLAUSIBLE_HEIGHT_UM,
                    MAX_PLAUSIBLE_HEIGHT_UM, "the given maximum height", reporter);
        }
        double rawRangeUm = raw.maxHeightUm() - raw.minHeightUm();
        if (levelling == null) {
            levelling = Levelling.defaultFor(format.isInstrumentFile());
            if (levelling != Levelling.NONE) {
                reporter.info(file + ": " + levelling.label() + " levelled (the default for " + format.words()
                        + "; a levelling of none keeps the heights as read)");
            }
        }
        HeightField levelled = levelling.apply(raw);
        double rangeUm = levelled.maxHeightUm() - levelled.minHeightUm();
        if (rawRangeUm == 0) {
            reporter.warn(file + ": the height field is flat (every sample is " + ReaderSupport.num(raw.minHeightUm())
                    + " um): it only reflects specularly and shows no diffraction colours");
        } else if (rangeUm <= 1e-9 * rawRangeUm) {
            reporter.warn(file + ": levelling (" + levelling.label() + ") leaves the height field flat: it is "
                    + (levelling == Levelling.ROWS ? "constant along every row" : "a tilted plane") + " without"
                    + " structure, which only reflects specularly and shows no diffraction colours");
        } else if (format != ScanFormat.IMAGE) {
            if (maxHeightUm != null) {
                levelled = rescaled(file, levelled, rangeUm, maxHeightUm, reporter);
            } else {
                // Heights came from the file: a wrong unit shows up as an implausible peak-to-valley height.
                ReaderSupport.warnIfImplausible(file, "peak-to-valley height", rangeUm, "", MIN_PLAUSIBLE_HEIGHT_UM,
                        MAX_PLAUSIBLE_HEIGHT_UM, switch (format) {
                            case GSF -> "the file's heights and ZUnits";
                            case TEXT -> "the file's heights, read as micrometres";
                            default -> "the channel's heights and unit";
                        }, reporter);
            }
        }
        return levelled.meanSubtracted();
    }

    /**
     * The channels of an instrument's file (each with its index, title, unit and size); empty for the formats that
     * hold one height field.
     *
     * @throws UserInputException for a file that cannot be read
     */
    public static List<ScanChannel> channels(Path file, Reporter reporter) {
        byte[] bytes = readBytes(file);
        return channels(file, ScanFormat.detect(file, bytes), bytes, reporter);
    }

    /** The format of a file by its content (else its extension), as every command reads it. */
    public static ScanFormat formatOf(Path file) {
        return ScanFormat.detect(file, readBytes(file));
    }

    private static List<ScanChannel> channels(Path file, ScanFormat format, byte[] bytes, Reporter reporter) {
        return switch (format) {
            case GWY -> GwyReader.channels(file, bytes, reporter);
            case IBW -> IbwReader.channels(file, bytes);
            case NANOSCOPE -> NanoscopeReader.channels(file, bytes);
            case JPK -> JpkReader.channels(file, bytes);
            case PARK -> ParkReader.channels(file, bytes);
            case MDT -> MdtReader.channels(file, bytes);
            case NID -> NidReader.channels(file, bytes);
            default -> List.of();
        };
    }

    /** A file whose content is another format than its name says is read as what it is, and told so. */
    private static void nameIfUnexpected(Path file, ScanFormat format, Reporter reporter) {
        if (!format.matchesExtension(file)) {
            reporter.info(file + ": read as " + format.words() + " (found by its content)");
        }
    }

    /**
     * The DFT of a field with fewer than 2 samples along an axis holds only its mean there, and a scan narrower
     * than the shortest visible wavelength has its first order beyond the horizon at normal incidence: neither
     * shows anything but the mirror reflection.
     */
    private static void requireResolvingSize(Path file, HeightField field) {
        String size = field.cols() + " x " + field.rows() + " samples (columns x rows)";
        // an axis along which the field does not change (a 1-D grating's grooves) needs no extent: its transform is
        // the mean there, whatever its size; an axis with structure needs two samples and a wavelength's width
        boolean alongX = tooSmall(field.cols(), field.widthUm()) && (varies(field, true) || !fits(field, false));
        boolean alongY = tooSmall(field.rows(), field.heightExtentUm()) && (varies(field, false) || !fits(field, true));
        if (!alongX && !alongY) {
            return;
        }
        if (field.rows() < 2 && field.cols() < 2 || (alongX ? field.cols() : field.rows()) < 2) {
            throw new UserInputException(file + ": the scan is " + size + "; its transform needs at least 2 samples"
                    + " along an axis with structure to hold any spatial frequency beside the mean, so it diffracts"
                    + " nothing; use a larger scan");
        }
        double widthUm = field.widthUm();
        double heightUm = field.heightExtentUm();
        throw new UserInputException(file + ": the scan is " + ReaderSupport.num(widthUm) + " x "
                + ReaderSupport.num(heightUm) + " um (" + size + " of " + ReaderSupport.num(field.pixelSizeXUm())
                + " x " + ReaderSupport.num(field.pixelSizeYUm()) + " um), narrower than the shortest visible"
                + " wavelength " + ReaderSupport.num(MIN_EXTENT_UM) + " um along " + (alongX ? "x" : "y")
                + ": its first diffraction order (sin theta = lambda / width > 1) lies beyond the horizon, so it shows"
                + " only the mirror reflection; use a larger scan, or check the pixel size");
    }

    private static boolean tooSmall(int samples, double extentUm) {
        return samples < 2 || extentUm < MIN_EXTENT_UM;
    }

    /** Whether the other axis holds the structure: enough samples and extent along it. */
    private static boolean fits(HeightField field, boolean alongX) {
        return alongX ? !tooSmall(field.cols(), field.widthUm()) : !tooSmall(field.rows(), field.heightExtentUm());
    }

    /** Whether the heights change along x (within some row) or along y (within some column). */
    private static boolean varies(HeightField field, boolean alongX) {
        for (int r = 0; r < field.rows(); r++) {
            for (int c = 0; c < field.cols(); c++) {
                double neighbour = alongX ? field.heightUm(r, 0) : field.heightUm(0, c);
                if (field.heightUm(r, c) != neighbour) {
                    return true;
                }
            }
        }
        return false;
    }

    private static void checkOption(Path file, Quantity quantity, Double valueUm, String meaning) {
        if (valueUm != null && (!(valueUm > 0) || !Double.isFinite(valueUm))) {
            throw new InvalidSettingException(quantity, file + ": " + quantity.words() + " " + valueUm
                    + " is not valid; it must be a positive number, " + meaning);
        }
    }

    private static void requireImageOptions(Path file, Double maxHeightUm, Double pixelSizeUm) {
        if (maxHeightUm == null) {
            throw new InvalidSettingException(Quantity.MAX_HEIGHT, file + ": an image carries no height scale; give"
                    + " the height in micrometres that white maps to" + (pixelSizeUm == null
                    ? ", and the pixel size (it carries none either)" : ""));
        }
        if (pixelSizeUm == null) {
            throw new InvalidSettingException(Quantity.PIXEL_SIZE, file + ": an image carries no pixel size; give"
                    + " the pixel size (the sample spacing in micrometres)");
        }
    }

    private static byte[] readBytes(Path file) {
        if (!Files.exists(file)) {
            throw new UserInputException(file + ": no such file; check the path");
        }
        if (Files.isDirectory(file)) {
            throw new UserInputException(file + ": is a directory; pass a height-field file (" + SUPPORTED + ")");
        }
        byte[] bytes;
        try {
            long size = Files.size(file);
            if (size > Integer.MAX_VALUE - 8) {
                throw new UserInputException(file + ": the file is " + size + " bytes, larger than a height field"
                        + " diffract reads (2 GB); crop the scan");
            }
            ReaderSupport.requireHeap(file, size / 8 + 1, "the file");
            bytes = Files.readAllBytes(file);
        } catch (IOException | OutOfMemoryError e) {
            // OutOfMemoryError: readAllBytes refuses files over 2 GiB with one, and the array is gone again.
            throw new UserInputException(file + ": cannot be read (" + e.getClass().getSimpleName()
                    + (e.getMessage() == null ? "" : ": " + e.getMessage().replaceAll("\\s+", " "))
                    + "); check its permissions", e);
        }
        if (bytes.length == 0) {
            throw new UserInputException(file + ": the file is empty (0 bytes); export the height field again");
        }
        return bytes;
    }

    private static void warnAboutPixelSize(Path file, ScanFormat format, HeightField field, Double pixelSizeUm,
                                           Reporter reporter) {
        String source = pixelSizeUm != null ? "the given pixel size" : switch (format) {
            case GWY -> "xreal/xres, yreal/yres of the data field";
            case IBW -> "the wave's step per point (sfA)";
            case GSF -> "XReal/XRes, YReal/YRes in the header";
            default -> "the scan size in the file's header";
        };
        boolean square = field.pixelSizeYUm() == field.pixelSizeXUm();
        ReaderSupport.warnIfImplausible(file, square ? "pixel size" : "pixel size along x", field.pixelSizeXUm(),
                "per pixel", MIN_PLAUSIBLE_PIXEL_UM, MAX_PLAUSIBLE_PIXEL_UM, source, reporter);
        if (!square) {
            ReaderSupport.warnIfImplausible(file, "pixel size along y", field.pixelSizeYUm(), "per pixel",
                    MIN_PLAUSIBLE_PIXEL_UM, MAX_PLAUSIBLE_PIXEL_UM, source, reporter);
        }
    }

    private static HeightField rescaled(Path file, HeightField raw, double rangeUm, double maxHeightUm,
                                        Reporter reporter) {
        double scale = maxHeightUm / rangeUm;
        double[] heightsUm = raw.heightsUm();
        for (int i = 0; i < heightsUm.length; i++) {
            heightsUm[i] *= scale;
        }
        reporter.info(file + ": heights rescaled by " + ReaderSupport.num(scale) + " so that max - min = "
                + ReaderSupport.num(maxHeightUm) + " um (the given maximum height; the file's is "
                + ReaderSupport.num(rangeUm) + " um)");
        return ReaderSupport.build(file, raw.rows(), raw.cols(), heightsUm, raw.pixelSizeXUm(), raw.pixelSizeYUm());
    }
}
