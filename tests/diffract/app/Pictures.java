package diffract.app;

import diffract.viewer.ViewerRenderer;

import java.awt.image.BufferedImage;

/** Counting pixels of rendered pictures, for the CLI tests. */
final class Pictures {
    private Pictures() {
    }

    /** A test on one 8-bit pixel's channels. */
    interface PixelTest {
        boolean test(int r, int g, int b);
    }

    /** Pixels that are clearly coloured rather than grey: the channels spread by more than 40 of 255. */
    static final PixelTest COLOURED = (r, g, b) -> Math.max(r, Math.max(g, b)) - Math.min(r, Math.min(g, b)) > 40;

    static int count(BufferedImage image, PixelTest test) {
        int n = 0;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                int p = image.getRGB(x, y);
                n += test.test(p >> 16 & 0xff, p >> 8 & 0xff, p & 0xff) ? 1 : 0;
            }
        }
        return n;
    }

    /** The viewer's background colour as 0xRRGGBB. */
    static int clearColour() {
        return Math.round(ViewerRenderer.CLEAR_COLOUR[0] * 255) << 16
                | Math.round(ViewerRenderer.CLEAR_COLOUR[1] * 255) << 8 | Math.round(ViewerRenderer.CLEAR_COLOUR[2] * 255);
    }
}
