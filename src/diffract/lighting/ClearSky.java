package diffract.lighting;

/**
 * A procedural clear sky as an environment map: the CIE clear-sky luminance distribution (CIE 110-1994; CIE S 011
 * standard sky type 12) relative to the zenith,
 * L(theta, gamma) / L_z = [(1 - exp(-0.32 / cos theta)) (0.91 + 10 exp(-3 gamma) + 0.45 cos^2 gamma)]
 * / [(1 - exp(-0.32)) (0.91 + 10 exp(-3 theta_s) + 0.45 cos^2 theta_s)],
 * theta the zenith angle of the sky element, gamma its angle from the sun, theta_s the sun's zenith angle; in a
 * uniform sky-blue colour (linear sRGB {@link #SKY_RGB}, a chromaticity near 12,000 K), scaled so that the sky
 * delivers {@code irradianceRatio} times the sun's normal irradiance (the key light, 1) to a horizontal surface
 * (about 0.15 to 0.3 on clear days). The sun itself is the scene's key light, not part of the map. Below the
 * horizon the ground reflects sun and sky diffusely: radiance albedo (E_sky + cos theta_s) / pi, in the ground's
 * colour.
 */
public final class ClearSky {
    /** Linear sRGB of clear-sky blue with luminance 1. */
    static final double[] SKY_RGB = {0.62, 0.79, 1.37};

    private ClearSky() {
    }

    /**
     * @param towardsSun      unit vector towards the sun (the key light), world frame, y up
     * @param irradianceRatio the sky's irradiance on a horizontal surface over the sun's normal irradiance
     * @param groundRgb       the ground's linear albedo
     */
    public static LatLongMap map(double[] towardsSun, double irradianceRatio, double[] groundRgb, int width,
                                 int height) {
        double sunZenith = Math.acos(Math.max(-1, Math.min(1, towardsSun[1])));
        double zenithTerm = (1 - Math.exp(-0.32)) * (0.91 + 10 * Math.exp(-3 * sunZenith)
                + 0.45 * Math.cos(sunZenith) * Math.cos(sunZenith));
        double[] relative = new double[width * height];
        double horizontal = 0;
        for (int r = 0; r < height; r++) {
            double omega = 2 * Math.PI / width * (Math.cos(Math.PI * r / height) - Math.cos(Math.PI * (r + 1) / height));
            for (int c = 0; c < width; c++) {
                double theta = Math.PI * (r + 0.5) / height;
                if (theta >= Math.PI / 2) {
                    continue;
                }
                double phi = 2 * Math.PI * (c + 0.5) / width;
                double[] d = {Math.sin(theta) * Math.sin(phi), Math.cos(theta), Math.sin(theta) * Math.cos(phi)};
                double cosGamma = Math.max(-1, Math.min(1, d[0] * towardsSun[0] + d[1] * towardsSun[1]
                        + d[2] * towardsSun[2]));
                double gamma = Math.acos(cosGamma);
                double l = (1 - Math.exp(-0.32 / Math.max(1e-3, Math.cos(theta))))
                        * (0.91 + 10 * Math.exp(-3 * gamma) + 0.45 * cosGamma * cosGamma) / zenithTerm;
                relative[r * width + c] = l;
                horizontal += l * Math.cos(theta) * omega;
            }
        }
        double scale = irradianceRatio / horizontal;
        double groundIrradiance = irradianceRatio + Math.max(0, towardsSun[1]);
        float[] rgb = new float[3 * width * height];
        for (int r = 0; r < height; r++) {
            boolean below = Math.PI * (r + 0.5) / height >= Math.PI / 2;
            for (int c = 0; c < width; c++) {
                for (int k = 0; k < 3; k++) {
                    rgb[3 * (r * width + c) + k] = (float) (below ? groundRgb[k] * groundIrradiance / Math.PI
                            : relative[r * width + c] * scale * SKY_RGB[k]);
                }
            }
        }
        return new LatLongMap(width, height, rgb);
    }
}
