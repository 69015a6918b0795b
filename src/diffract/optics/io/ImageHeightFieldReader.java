package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.util.Reporter;
import diffract.util.UserInputException;

import javax.imageio.ImageIO;
import java.awt.color.ColorSpace;
import java.awt.image.BufferedImage;
import java.awt.image.ColorModel;
import java.awt.image.DataBuffer;
import java.awt.image.IndexColorModel;
import java.awt.image.Raster;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Path;

/**
 * Grey-scale height images (PNG, BMP, TIFF through the JDK's ImageIO): grey 0..max maps linearly to
 * 0..maxHeightUm, where max is 2^bits - 1 of the stored samples (255, 65535). Samples are read from the
 * Raster, never through getRGB, which would squeeze 16-bit heights into 8 bits. Colour pixels become grey by
 * Rec. 709 luminance on the stored (not linearised) values; palette pixels go through their palette entry.
 */
final class ImageHeightFieldReader {
    // Rec. 709 / sRGB luminance weights, applied to the stored component values.
    private static final double WEIGHT_R = 0.2126;
    private static final double WEIGHT_G = 0.7152;
    private static final double WEIGHT_B = 0.0722;

    private ImageHeightFieldReader() {
    }

    static HeightField read(Path file, byte[] bytes, double maxHeightUm, double pixelSizeUm, Reporter reporter) {
        BufferedImage image = decode(file, bytes);
        int cols = image.getWidth();
        int rows = image.getHeight();
        if ((long) rows * cols > Integer.MAX_VALUE - 8) {
            throw new UserInputException(file + ": the image is too large (" + cols + " x " + rows
                    + " pixels); crop it to the patch you need");
        }
        double[] normalised = normalisedGrey(file, image, reporter);
        double[] heightsUm = new double[normalised.length];
        for (int i = 0; i < heightsUm.length; i++) {
            heightsUm[i] = normalised[i] * maxHeightUm;
        }
        return ReaderSupport.build(file, rows, cols, heightsUm, pixelSizeUm, pixelSizeUm);
    }

    private static BufferedImage decode(Path file, byte[] bytes) {
        BufferedImage image;
        try {
            image = ImageIO.read(new ByteArrayInputStream(bytes));
        } catch (IOException | RuntimeException e) {
            // Decoders throw anything from IIOException to ArrayIndexOutOfBounds on damaged files.
            throw new UserInputException(file + ": the image is corrupt or truncated and cannot be decoded ("
                    + oneLine(e) + "); re-export it as an 8- or 16-bit grey PNG or TIFF", e);
        }
        if (image == null) {
            throw new UserInputException(file + ": not a readable image (no PNG, BMP or TIFF decoder accepts it);"
                    + " re-export it as an 8- or 16-bit grey PNG or TIFF");
        }
        if (image.getWidth() <= 0 || image.getHeight() <= 0) {
            throw new UserInputException(file + ": the image has no pixels (" + image.getWidth() + " x "
                    + image.getHeight() + "); export the height map again");
        }
        return image;
    }

    private static String oneLine(Exception e) {
        String message = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
        return message.replaceAll("\\s+", " ").trim();
    }

    /** Grey in [0, 1] per pixel, row-major from the top-left. */
    private static double[] normalisedGrey(Path file, BufferedImage image, Reporter reporter) {
        Raster raster = image.getRaster();
        ColorModel colorModel = image.getColorModel();
        int dataType = raster.getSampleModel().getDataType();
        if (dataType == DataBuffer.TYPE_FLOAT || dataType == DataBuffer.TYPE_DOUBLE) {
            // Float images carry physical values whose unit the image cannot tell us; a silent guess would
            // scale the heights by an unknown factor.
            throw new UserInputException(file + ": floating-point images are not supported (their unit is unknown);"
                    + " export the heights as a Gwyddion .gsf or a text matrix, or as an 8- or 16-bit grey image");
        }
        int cols = raster.getWidth();
        int rows = raster.getHeight();
        double[] out = new double[rows * cols];
        if (colorModel instanceof IndexColorModel palette) {
            readPalette(raster, palette, out, cols, rows, file, reporter);
            return out;
        }
        int colourSpace = colorModel.getColorSpace().getType();
        int colourBands = colorModel.getNumColorComponents();
        if (colourSpace == ColorSpace.TYPE_GRAY && colourBands == 1) {
            double max = maxSample(raster, 0);
            for (int y = 0; y < rows; y++) {
                for (int x = 0; x < cols; x++) {
                    out[y * cols + x] = unsigned(raster.getSample(x, y, 0), raster, 0) / max;
                }
            }
        } else if (colourSpace == ColorSpace.TYPE_RGB && colourBands == 3) {
            // Raster bands follow the colour model's component order (R, G, B[, A]) whatever the byte layout.
            double maxR = maxSample(raster, 0);
            double maxG = maxSample(raster, 1);
            double maxB = maxSample(raster, 2);
            boolean colourful = false;
            for (int y = 0; y < rows; y++) {
                for (int x = 0; x < cols; x++) {
                    double r = unsigned(raster.getSample(x, y, 0), raster, 0) / maxR;
                    double g = unsigned(raster.getSample(x, y, 1), raster, 1) / maxG;
                    double b = unsigned(raster.getSample(x, y, 2), raster, 2) / maxB;
                    out[y * cols + x] = luminance(r, g, b);
                    colourful |= r != g || g != b;
                }
            }
            if (colourful) {
                warnColourful(file, reporter);
            }
        } else {
            throw new UserInputException(file + ": unsupported colour space (" + colourBands
                    + " colour components, not grey or RGB); save the height map as a grey PNG or TIFF");
        }
        if (colorModel.hasAlpha()) {
            warnIfTransparent(file, raster, colourBands, reporter);
        }
        return out;
    }

    private static void readPalette(Raster raster, IndexColorModel palette, double[] out, int cols, int rows,
                                    Path file, Reporter reporter) {
        boolean colourful = false;
        boolean transparent = false;
        for (int y = 0; y < rows; y++) {
            for (int x = 0; x < cols; x++) {
                int index = raster.getSample(x, y, 0);
                int r = palette.getRed(index);
                int g = palette.getGreen(index);
                int b = palette.getBlue(index);
                out[y * cols + x] = luminance(r / 255.0, g / 255.0, b / 255.0);
                colourful |= r != g || g != b;
                transparent |= palette.getAlpha(index) != 255;
            }
        }
        if (colourful) {
            warnColourful(file, reporter);
        }
        if (transparent) {
            reporter.warn(file + ": the image has transparent pixels; transparency is ignored, heights come from"
                    + " the grey values");
        }
    }

    /** Grey pixels keep their exact value: the weights' floating-point sum is not exactly 1. */
    private static double luminance(double r, double g, double b) {
        if (r == g && g == b) {
            return r;
        }
        return WEIGHT_R * r + WEIGHT_G * g + WEIGHT_B * b;
    }

    private static void warnColourful(Path file, Reporter reporter) {
        // A false-colour rendering (e.g. an AFM viewer's colour map) is not a height map: its luminance is
        // not monotonic in height.
        reporter.warn(file + ": the image has colour pixels; heights are taken from their luminance"
                + " (0.2126 R + 0.7152 G + 0.0722 B), which is wrong for a false-colour rendering;"
                + " export the raw heights as grey instead");
    }

    private static void warnIfTransparent(Path file, Raster raster, int alphaBand, Reporter reporter) {
        // (int) of the all-ones value: for 32-bit alpha that is -1, which is what getSample returns.
        int opaque = (int) ((1L << raster.getSampleModel().getSampleSize(alphaBand)) - 1);
        for (int y = 0; y < raster.getHeight(); y++) {
            for (int x = 0; x < raster.getWidth(); x++) {
                if (raster.getSample(x, y, alphaBand) != opaque) {
                    reporter.warn(file + ": the image has transparent pixels; transparency is ignored, heights"
                            + " come from the grey values");
                    return;
                }
            }
        }
    }

    private static double maxSample(Raster raster, int band) {
        int bits = raster.getSampleModel().getSampleSize(band);
        return (double) ((1L << bits) - 1);
    }

    /** 32-bit integer samples come back as signed ints; other depths are already non-negative. */
    private static double unsigned(int sample, Raster raster, int band) {
        return raster.getSampleModel().getSampleSize(band) == 32 ? Integer.toUnsignedLong(sample) : sample;
    }
}
