package diffract.optics.io;

import diffract.optics.HeightField;
import diffract.optics.InvalidSettingException;
import diffract.optics.Quantity;
import diffract.util.Reporter;
import diffract.util.UserInputException;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Loads a nanostructure height field from a file and returns it mean-subtracted, as the thesis' precompute
 * uses it. Formats, chosen by content (PNG, BMP, TIFF and GSF signatures) and otherwise by extension:
 * <ul>
 *   <li>grey images (.png, .bmp, .tif, .tiff; 8 or 16 bits, colour via luminance): grey 0..max maps linearly
 *       to 0..{@code maxHeightUm}; needs {@code maxHeightUm} and {@code pixelSizeUm};</li>
 *   <li>text matrices (.txt, .csv, .asc, .dat): heights in micrometres, one row per line; needs
 *       {@code pixelSizeUm};</li>
 *   <li>Gwyddion Simple Field (.gsf): heights and pixel sizes from the file (metres by default), converted to
 *       micrometres; {@code pixelSizeUm}, if given, overrides the file's.</li>
 * </ul>
 * For text and GSF a given {@code maxHeightUm} rescales the heights so that max - min equals it. Every problem
 * with the input is a one-line {@link UserInputException} naming the file; implausible values (a pixel size
 * or height that looks like it is in the wrong unit, a flat field) are warnings on the {@link Reporter}.
 */
public final class HeightFieldReader {
    /** Plausible lateral sampling of an AFM patch: 1 nm to 10 um per pixel. */
    static final double MIN_PLAUSIBLE_PIXEL_UM = 0.001;
    static final double MAX_PLAUSIBLE_PIXEL_UM = 10.0;
    /** Plausible peak-to-valley height of a diffracting nanostructure: 1 nm to 20 um. */
    static final double MIN_PLAUSIBLE_HEIGHT_UM = 0.001;
    static final double MAX_PLAUSIBLE_HEIGHT_UM = 20.0;

    static final String SUPPORTED = ".png, .bmp, .tif, .tiff (grey images), .txt, .csv, .asc, .dat (text matrices),"
            + " .gsf (Gwyddion Simple Field)";

    private enum Format { IMAGE, TEXT, GSF }

    private HeightFieldReader() {
    }

    /**
     * @param file        the height-field file
     * @param maxHeightUm the height of the brightest grey value (images, required), or the peak-to-valley height
     *                    to rescale to (text, GSF, optional); null when not given
     * @param pixelSizeUm the sample spacing in micrometres (images and text, required; GSF, optional override);
     *                    null when not given
     * @param reporter    receives plausibility warnings and notes
     * @return the field with its mean subtracted
     * @throws UserInputException for any problem with the file or the options
     */
    public static HeightField load(Path file, Double maxHeightUm, Double pixelSizeUm, Reporter reporter) {
        checkOption(file, Quantity.MAX_HEIGHT, maxHeightUm,
                "the peak-to-valley height of the structure in micrometres");
        checkOption(file, Quantity.PIXEL_SIZE, pixelSizeUm, "the sample spacing in micrometres");
        byte[] bytes = readBytes(file);
        Format format = detect(file, bytes);

        HeightField raw;
        switch (format) {
            case IMAGE:
                requireImageOptions(file, maxHeightUm, pixelSizeUm);
                raw = ImageHeightFieldReader.read(file, maxHeightUm, pixelSizeUm, reporter);
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
                throw new IllegalStateException("unhandled format " + format);
        }

        warnAboutPixelSize(file, raw, pixelSizeUm, reporter);
        double rangeUm = raw.maxHeightUm() - raw.minHeightUm();
        if (maxHeightUm != null) {
            ReaderSupport.warnIfImplausible(file, "maximum height", maxHeightUm, "", MIN_PLAUSIBLE_HEIGHT_UM,
                    MAX_PLAUSIBLE_HEIGHT_UM, "the given maximum height", reporter);
        }
        if (rangeUm == 0) {
            reporter.warn(file + ": the height field is flat (every sample is " + ReaderSupport.num(raw.minHeightUm())
                    + " um): it only reflects specularly and shows no diffraction colours");
        } else if (format != Format.IMAGE) {
            if (maxHeightUm != null) {
                raw = rescaled(file, raw, rangeUm, maxHeightUm, reporter);
            } else {
                // Heights came from the file: a wrong unit shows up as an implausible peak-to-valley height.
                ReaderSupport.warnIfImplausible(file, "peak-to-valley height", rangeUm, "", MIN_PLAUSIBLE_HEIGHT_UM,
                        MAX_PLAUSIBLE_HEIGHT_UM, format == Format.GSF ? "the file's heights and ZUnits"
                                : "the file's heights, read as micrometres", reporter);
            }
        }
        return raw.meanSubtracted();
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

    /** Signatures first, so a mis-named file still loads; the extension decides for text. */
    private static Format detect(Path file, byte[] bytes) {
        if (GsfReader.looksLikeGsf(bytes)) {
            return Format.GSF;
        }
        if (startsWith(bytes, 0x89, 'P', 'N', 'G') || startsWith(bytes, 'B', 'M')
                || startsWith(bytes, 'I', 'I', 42, 0) || startsWith(bytes, 'M', 'M', 0, 42)) {
            return Format.IMAGE;
        }
        String name = file.getFileName() == null ? "" : file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String extension = dot < 0 ? "" : name.substring(dot + 1).toLowerCase(Locale.ROOT);
        switch (extension) {
            case "png":
            case "bmp":
            case "tif":
            case "tiff":
                return Format.IMAGE; // the decoder will say it is damaged
            case "txt":
            case "csv":
            case "asc":
            case "dat":
                return Format.TEXT;
            case "gsf":
                return Format.GSF; // GsfReader explains what the first line should be
            default:
                throw new UserInputException(file + ": unsupported file type"
                        + (extension.isEmpty() ? " (no extension)" : " '." + extension + "'")
                        + "; supported: " + SUPPORTED);
        }
    }

    private static boolean startsWith(byte[] bytes, int... signature) {
        if (bytes.length < signature.length) {
            return false;
        }
        for (int i = 0; i < signature.length; i++) {
            if ((bytes[i] & 0xFF) != signature[i]) {
                return false;
            }
        }
        return true;
    }

    private static void warnAboutPixelSize(Path file, HeightField field, Double pixelSizeUm, Reporter reporter) {
        String source = pixelSizeUm != null ? "the given pixel size" : "XReal/XRes, YReal/YRes in the header";
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
