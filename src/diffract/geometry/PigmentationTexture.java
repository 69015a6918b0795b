package diffract.geometry;

import diffract.util.UserInputException;

import java.awt.image.BufferedImage;

/**
 * A procedural corn-snake-like (Pantherophis / Elaphe guttata) skin colour in the UV layout of {@link SnakeMesh}:
 * red-orange saddles edged in black along the back, smaller blotches in two alternating rows on each flank, on a
 * lighter orange-tan ground, and a black-and-white chequered belly. A seeded value noise roughens the blotch
 * outlines and varies their size, so no two saddles are alike and the same seed always gives the same image.
 *
 * <p>Layout: pixel column x covers u = (x + 0.5) / width (around the body: 0 belly, 0.5 back), pixel row y covers
 * v = 1 - (y + 0.5) / height (along the body: row 0 is the tail tip, the last row the snout), matching an image
 * uploaded bottom row first as OpenGL textures are. The pattern wraps seamlessly in u.
 */
public final class PigmentationTexture {
    /** Ground, saddle, edge and belly colours, sRGB: chosen by eye from photographs of corn snakes. */
    static final int GROUND = rgb(222, 150, 96);
    static final int SADDLE = rgb(196, 58, 34);
    static final int EDGE = rgb(22, 14, 10);
    static final int BELLY_LIGHT = rgb(236, 228, 210);

    /**
     * @param saddles          dorsal saddles from snout to tail tip
     * @param saddleHalfWidthU half-width of a saddle around the body, as a fraction of the circumference
     * @param edgeWidth        width of the black edge as a fraction of a blotch's radius
     * @param roughness        amplitude of the noise on the blotch outlines, as a fraction of a blotch's radius
     * @param seed             noise seed
     */
    public record Parameters(int saddles, double saddleHalfWidthU, double edgeWidth, double roughness, long seed) {
        public Parameters {
            if (saddles < 1 || saddles > 500) {
                throw new UserInputException("pigmentation saddles must be in [1, 500], got " + saddles);
            }
            if (!(saddleHalfWidthU > 0 && saddleHalfWidthU < 0.25)) {
                throw new UserInputException("pigmentation saddleHalfWidthU must be in (0, 0.25), got "
                        + saddleHalfWidthU);
            }
            if (!(edgeWidth >= 0 && edgeWidth < 0.6)) {
                throw new UserInputException("pigmentation edgeWidth must be in [0, 0.6), got " + edgeWidth);
            }
            if (!(roughness >= 0 && roughness <= 0.5)) {
                throw new UserInputException("pigmentation roughness must be in [0, 0.5], got " + roughness);
            }
        }

        /** About 45 saddles, as on a corn snake; a quarter of the circumference wide. */
        public static Parameters defaults(long seed) {
            return new Parameters(45, 0.12, 0.22, 0.18, seed);
        }
    }

    private final Parameters parameters;
    private final ValueNoise noise;

    public PigmentationTexture(Parameters parameters) {
        this.parameters = parameters;
        this.noise = new ValueNoise(parameters.seed());
    }

    /** The texture as an sRGB image of the given size (width around the body, height along it). */
    public BufferedImage image(int widthPx, int heightPx) {
        if (widthPx < 1 || heightPx < 1 || (long) widthPx * heightPx > 64L * 1024 * 1024) {
            throw new UserInputException("pigmentation texture size must be 1..64 Mpixel, got " + widthPx + " x "
                    + heightPx);
        }
        BufferedImage image = new BufferedImage(widthPx, heightPx, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < heightPx; y++) {
            double v = 1 - (y + 0.5) / heightPx;
            for (int x = 0; x < widthPx; x++) {
                image.setRGB(x, y, colourAt((x + 0.5) / widthPx, v));
            }
        }
        return image;
    }

    /** The sRGB colour (0xRRGGBB) at texture coordinates (u, v). */
    public int colourAt(double u, double v) {
        double belly = Math.min(u, 1 - u); // distance around the body from the belly midline, 0..0.5
        if (belly < 0.11) {
            return bellyColour(u, v);
        }
        double spacingV = 1.0 / parameters.saddles();
        // dorsal saddles, centred on u = 0.5
        double colour = blotch(u - 0.5, v, spacingV, 0, parameters.saddleHalfWidthU(), 0.32 * spacingV, 0);
        if (colour >= 0) {
            return colour > 0 ? SADDLE : EDGE;
        }
        // flank blotches: half as large, between the saddles, on both sides
        for (int side = -1; side <= 1; side += 2) {
            double sideU = u - 0.5 - side * 0.25;
            colour = blotch(sideU, v, spacingV, 0.5, 0.045, 0.2 * spacingV, side);
            if (colour >= 0) {
                return colour > 0 ? SADDLE : EDGE;
            }
        }
        // the ground is mottled a little, as real skin is
        double shade = 1 - 0.08 * noise.at(wrap(u) * 64, v * 400, 3);
        return scale(GROUND, shade);
    }

    /**
     * Tests one row of blotches: returns 1 inside a blotch, 0 on its black edge, -1 outside.
     *
     * @param du          u offset from the row's centre line (wrapped into [-0.5, 0.5))
     * @param phase       where along a spacing the blotches sit (0 = on multiples of the spacing)
     * @param halfWidthU  blotch half-width around the body
     * @param halfLengthV blotch half-length along the body
     */
    private double blotch(double du, double v, double spacingV, double phase, double halfWidthU,
                          double halfLengthV, int row) {
        du = du - Math.floor(du + 0.5);
        double position = v / spacingV - phase;
        long index = Math.round(position);
        double dv = (position - index) * spacingV;
        double sizeJitter = 1 + 0.25 * (noise.hash(index, row) - 0.5);
        // a rounded rectangle (superellipse, exponent 4): saddles are squarish with rounded corners
        double r = Math.pow(Math.pow(Math.abs(du) / (halfWidthU * sizeJitter), 4)
                + Math.pow(Math.abs(dv) / (halfLengthV * sizeJitter), 4), 0.25);
        // rough outline: noise in u wraps with the body (period 1), in v it is just long
        r += parameters.roughness() * (noise.at(wrap(du + 0.5) * 64, v * 700, row + 7) - 0.5) * 2;
        if (r > 1) {
            return -1;
        }
        return r > 1 - parameters.edgeWidth() ? 0 : 1;
    }

    /** Belly: rows of black checks, alternating sides, on a cream ground. */
    private int bellyColour(double u, double v) {
        double scalesPerLength = parameters.saddles() * 3.0;
        long scaleRow = (long) Math.floor(v * scalesPerLength);
        boolean leftHalf = u > 0.5;
        boolean dark = (scaleRow % 2 == 0) == leftHalf && noise.hash(scaleRow, 99) > 0.3;
        return dark ? EDGE : BELLY_LIGHT;
    }

    private static double wrap(double u) {
        return u - Math.floor(u);
    }

    private static int rgb(int r, int g, int b) {
        return (r << 16) | (g << 8) | b;
    }

    private static int scale(int rgb, double factor) {
        int r = (int) Math.round(Math.min(255, ((rgb >> 16) & 0xFF) * factor));
        int g = (int) Math.round(Math.min(255, ((rgb >> 8) & 0xFF) * factor));
        int b = (int) Math.round(Math.min(255, (rgb & 0xFF) * factor));
        return rgb(r, g, b);
    }

    /** Smooth 2-D value noise in [0, 1] on an integer lattice, seeded; the lattice wraps every 64 cells in x. */
    static final class ValueNoise {
        private static final int PERIOD_X = 64;
        private final long seed;

        ValueNoise(long seed) {
            this.seed = seed;
        }

        double at(double x, double y, int channel) {
            long x0 = (long) Math.floor(x);
            long y0 = (long) Math.floor(y);
            double fx = fade(x - x0);
            double fy = fade(y - y0);
            double a = lattice(x0, y0, channel);
            double b = lattice(x0 + 1, y0, channel);
            double c = lattice(x0, y0 + 1, channel);
            double d = lattice(x0 + 1, y0 + 1, channel);
            return lerp(lerp(a, b, fx), lerp(c, d, fx), fy);
        }

        private double lattice(long x, long y, int channel) {
            return hash(Math.floorMod(x, PERIOD_X) + 1_000_003L * y, channel);
        }

        /** A uniform number in [0, 1) from two integers and the seed (SplitMix64 finaliser). */
        double hash(long a, long b) {
            long z = seed * 0x9E3779B97F4A7C15L + a * 0xBF58476D1CE4E5B9L + b * 0x94D049BB133111EBL;
            z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
            z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
            z ^= z >>> 31;
            return (z >>> 11) * 0x1.0p-53;
        }

        private static double fade(double t) {
            return t * t * (3 - 2 * t);
        }

        private static double lerp(double a, double b, double t) {
            return a + (b - a) * t;
        }
    }
}
