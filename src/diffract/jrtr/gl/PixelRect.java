package diffract.jrtr.gl;

/**
 * A rectangle of whole pixels in OpenGL's window coordinates: {@code (x, y)} is the lower left corner, rows count
 * upwards from the bottom of the framebuffer.
 */
public record PixelRect(int x, int y, int width, int height) {
    public PixelRect {
        if (width < 0 || height < 0) {
            throw new IllegalArgumentException("negative size " + width + "x" + height);
        }
    }

    /** The whole of a {@code width} x {@code height} framebuffer. */
    public static PixelRect of(int width, int height) {
        return new PixelRect(0, 0, width, height);
    }

    public long area() {
        return (long) width * height;
    }

    public boolean isEmpty() {
        return width == 0 || height == 0;
    }

    /**
     * This rectangle of a {@code fromWidth} x {@code fromHeight} framebuffer mapped onto one of {@code toWidth} x
     * {@code toHeight} (each edge rounded to the nearest pixel, so adjacent rectangles stay adjacent).
     */
    public PixelRect scaled(int fromWidth, int fromHeight, int toWidth, int toHeight) {
        int x0 = edge(x, fromWidth, toWidth);
        int y0 = edge(y, fromHeight, toHeight);
        return new PixelRect(x0, y0, edge(x + width, fromWidth, toWidth) - x0, edge(y + height, fromHeight, toHeight) - y0);
    }

    private static int edge(int value, int from, int to) {
        return (int) Math.round((double) value * to / from);
    }
}
