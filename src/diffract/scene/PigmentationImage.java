package diffract.scene;

import diffract.util.UserInputException;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** Reads a pigmentation image (the skin's colour texture) with one-line errors for a missing or unreadable file. */
public final class PigmentationImage {
    private PigmentationImage() {
    }

    public static BufferedImage read(Path file) {
        if (!Files.isRegularFile(file)) {
            throw new UserInputException("pigmentation image " + file + " not found");
        }
        try {
            BufferedImage image = ImageIO.read(file.toFile());
            if (image == null) {
                throw new UserInputException(file + " is not an image Java can read (use PNG, JPEG or BMP)");
            }
            return image;
        } catch (IOException e) {
            throw new UserInputException("cannot read pigmentation image " + file + ": " + e.getMessage(), e);
        }
    }
}
