package diffract.geometry;

import diffract.util.UserInputException;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;

/**
 * A tangent-space normal map from an image (the common OpenGL convention: n = 2 rgb - 1, x along the mesh's tangent,
 * y along its bitangent N x T, z out of the surface; image row 0 at texture coordinate v = 1) turned into the frame
 * map the staged surface shader reads ({@link ScaledSkin#frameMap}'s layout): the normal's x and y per texel, the
 * patch's axis unchanged (1, 0), rows from v = 0.
 */
public final class NormalMapImage {
    private NormalMapImage() {
    }

    /** The frame map of an image: {width, height} in {@code size}, RGBA floats returned. */
    public static float[] frameMap(BufferedImage image) {
        int w = image.getWidth();
        int h = image.getHeight();
        float[] rgba = new float[4 * w * h];
        for (int y = 0; y < h; y++) {
            int row = h - 1 - y; // image row 0 is the top, v = 1
            for (int x = 0; x < w; x++) {
                int c = image.getRGB(x, y);
                double nx = 2 * (((c >> 16) & 0xFF) / 255.0) - 1;
                double ny = 2 * (((c >> 8) & 0xFF) / 255.0) - 1;
                double nz = 2 * ((c & 0xFF) / 255.0) - 1;
                double length = Math.sqrt(nx * nx + ny * ny + Math.max(0, nz) * Math.max(0, nz));
                int k = 4 * (row * w + x);
                if (length < 1e-6 || nz <= 0) { // no outward normal: the mesh's own
                    rgba[k + 2] = 1;
                    continue;
                }
                rgba[k] = (float) (nx / length);
                rgba[k + 1] = (float) (ny / length);
                rgba[k + 2] = 1;
                rgba[k + 3] = 0;
            }
        }
        return rgba;
    }

    public static BufferedImage read(Path file) {
        try {
            BufferedImage image = ImageIO.read(file.toFile());
            if (image == null) {
                throw new UserInputException("normal map " + file + ": not an image ImageIO reads (PNG, BMP, JPEG)");
            }
            if (image.getWidth() > 8192 || image.getHeight() > 8192) {
                throw new UserInputException("normal map " + file + ": at most 8192 x 8192 pixels");
            }
            return image;
        } catch (IOException e) {
            throw new UserInputException("cannot read normal map " + file + ": " + e.getMessage());
        }
    }
}
