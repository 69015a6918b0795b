package diffract.lighting;

/**
 * An environment map in the equirectangular (latitude-longitude) layout: linear RGB radiance per pixel, row 0 at the
 * zenith (+y, world up), the last row at the nadir; column c at azimuth phi = 2 pi (c + 0.5) / width measured from
 * +z towards +x. Pixel (c, r) looks along d = (sin theta sin phi, cos theta, sin theta cos phi), theta = pi (r + 0.5)
 * / height, and covers the solid angle (2 pi / width)(pi / height) sin theta (to first order; {@link #solidAngle}
 * integrates sin theta over the row exactly, so the pixels of a map cover 4 pi exactly).
 */
public final class LatLongMap {
    private final int width;
    private final int height;
    private final float[] rgb;

    /** @param rgb linear RGB triples, row-major from the top row; kept, not copied */
    public LatLongMap(int width, int height, float[] rgb) {
        if (width < 2 || height < 1 || rgb.length != 3 * width * height) {
            throw new IllegalArgumentException("a " + width + " x " + height + " map needs " + 3 * width * height
                    + " floats, got " + rgb.length);
        }
        for (float value : rgb) {
            if (!(value >= 0) || !Float.isFinite(value)) {
                throw new IllegalArgumentException("radiance must be finite and >= 0, got " + value);
            }
        }
        this.width = width;
        this.height = height;
        this.rgb = rgb;
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** A copy of the pixels. */
    public float[] rgb() {
        return rgb.clone();
    }

    public float get(int column, int row, int channel) {
        return rgb[3 * (row * width + column) + channel];
    }

    /** The solid angle of a pixel of row {@code row}, steradians: (2 pi / width)(cos theta_top - cos theta_bottom). */
    public double solidAngle(int row) {
        double top = Math.PI * row / height;
        double bottom = Math.PI * (row + 1) / height;
        return 2 * Math.PI / width * (Math.cos(top) - Math.cos(bottom));
    }

    /** The unit direction of a point of the map in pixel coordinates (column and row may be fractional). */
    public double[] direction(double column, double row) {
        double theta = Math.PI * row / height;
        double phi = 2 * Math.PI * column / width;
        return new double[] {Math.sin(theta) * Math.sin(phi), Math.cos(theta), Math.sin(theta) * Math.cos(phi)};
    }

    /** The centre direction of pixel (column, row). */
    public double[] pixelDirection(int column, int row) {
        return direction(column + 0.5, row + 0.5);
    }

    /** The map's pixel coordinates (column, row; fractional) of a unit direction. */
    public double[] pixelOf(double[] d) {
        double theta = Math.acos(Math.max(-1, Math.min(1, d[1])));
        double phi = Math.atan2(d[0], d[2]);
        if (phi < 0) {
            phi += 2 * Math.PI;
        }
        return new double[] {phi / (2 * Math.PI) * width, theta / Math.PI * height};
    }

    /** Integral of radiance over the sphere per channel: the irradiance sum of all lights a map stands for. */
    public double[] totalPower() {
        double[] sum = new double[3];
        for (int r = 0; r < height; r++) {
            double omega = solidAngle(r);
            for (int c = 0; c < width; c++) {
                for (int k = 0; k < 3; k++) {
                    sum[k] += get(c, r, k) * omega;
                }
            }
        }
        return sum;
    }

    /** This map with every radiance multiplied by {@code factor}. */
    public LatLongMap scaled(double factor) {
        float[] out = new float[rgb.length];
        for (int i = 0; i < out.length; i++) {
            out[i] = (float) (rgb[i] * factor);
        }
        return new LatLongMap(width, height, out);
    }

    /**
     * The map averaged down by an integer factor per axis (box filter weighted by solid angle), for the median cut
     * and the spherical harmonics, which need no more than a few hundred pixels across.
     */
    public LatLongMap downsampled(int factor) {
        if (factor <= 1) {
            return this;
        }
        int w = Math.max(2, width / factor);
        int h = Math.max(1, height / factor);
        float[] out = new float[3 * w * h];
        for (int r = 0; r < h; r++) {
            for (int c = 0; c < w; c++) {
                double[] sum = new double[3];
                double weight = 0;
                for (int rr = r * height / h; rr < (r + 1) * height / h; rr++) {
                    double omega = solidAngle(rr);
                    for (int cc = c * width / w; cc < (c + 1) * width / w; cc++) {
                        for (int k = 0; k < 3; k++) {
                            sum[k] += get(cc, rr, k) * omega;
                        }
                        weight += omega;
                    }
                }
                for (int k = 0; k < 3; k++) {
                    out[3 * (r * w + c) + k] = (float) (weight > 0 ? sum[k] / weight : 0);
                }
            }
        }
        return new LatLongMap(w, h, out);
    }

    /** This map turned about the world y axis by {@code degrees} (a direction d is seen at d turned by -degrees). */
    public LatLongMap rotatedAboutY(double degrees) {
        double shift = degrees / 360 * width;
        float[] out = new float[rgb.length];
        for (int r = 0; r < height; r++) {
            for (int c = 0; c < width; c++) {
                double source = c + 0.5 - shift - 0.5;
                int c0 = (int) Math.floor(source);
                double f = source - c0;
                for (int k = 0; k < 3; k++) {
                    out[3 * (r * width + c) + k] = (float) ((1 - f) * get(Math.floorMod(c0, width), r, k)
                            + f * get(Math.floorMod(c0 + 1, width), r, k));
                }
            }
        }
        return new LatLongMap(width, height, out);
    }
}
