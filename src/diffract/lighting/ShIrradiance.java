package diffract.lighting;

/**
 * Diffuse irradiance from an environment by nine spherical-harmonic coefficients (R. Ramamoorthi and P. Hanrahan,
 * "An Efficient Representation for Irradiance Environment Maps", SIGGRAPH 2001): L_lm = integral of L(w) Y_lm(w)
 * dw over the map, E(n) = sum_lm A_l L_lm Y_lm(n) with A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4. E(n) is the
 * integral of L(w) max(0, n.w) dw, the irradiance on a surface facing n (exact for environments of bands 0-2,
 * within a few per cent of the cosine lobe for others, as the paper shows).
 */
public final class ShIrradiance {
    private final double[] coefficients; // 9 x RGB: L_lm, in the order of basis()

    private ShIrradiance(double[] coefficients) {
        this.coefficients = coefficients;
    }

    /** Projects the map onto the first nine real spherical harmonics. */
    public static ShIrradiance of(LatLongMap map) {
        double[] l = new double[27];
        for (int r = 0; r < map.height(); r++) {
            double omega = map.solidAngle(r);
            for (int c = 0; c < map.width(); c++) {
                double[] y = basis(map.pixelDirection(c, r));
                for (int i = 0; i < 9; i++) {
                    for (int k = 0; k < 3; k++) {
                        l[3 * i + k] += map.get(c, r, k) * y[i] * omega;
                    }
                }
            }
        }
        return new ShIrradiance(l);
    }

    /** The nine real SH basis functions at a unit direction (x, y, z), bands 0, 1, 2. */
    static double[] basis(double[] d) {
        double x = d[0];
        double y = d[1];
        double z = d[2];
        return new double[] {
            0.282095,
            0.488603 * y, 0.488603 * z, 0.488603 * x,
            1.092548 * x * y, 1.092548 * y * z, 0.315392 * (3 * z * z - 1), 1.092548 * x * z,
            0.546274 * (x * x - y * y)};
    }

    /** A_l per basis function. */
    private static final double[] BAND_FACTOR = {Math.PI, 2 * Math.PI / 3, 2 * Math.PI / 3, 2 * Math.PI / 3,
        Math.PI / 4, Math.PI / 4, Math.PI / 4, Math.PI / 4, Math.PI / 4};

    /** Irradiance (linear RGB) on a surface whose unit normal is {@code n}. */
    public double[] irradiance(double[] n) {
        double[] y = basis(n);
        double[] e = new double[3];
        for (int i = 0; i < 9; i++) {
            for (int k = 0; k < 3; k++) {
                e[k] += BAND_FACTOR[i] * coefficients[3 * i + k] * y[i];
            }
        }
        return e;
    }

    /**
     * The nine RGB coefficients pre-multiplied by A_l and the basis constants, for a shader that evaluates
     * E(n) = c0 + c1 y + c2 z + c3 x + c4 xy + c5 yz + c6 (3 z^2 - 1) + c7 xz + c8 (x^2 - y^2) per channel.
     */
    public float[] shaderCoefficients() {
        double[] constants = {0.282095, 0.488603, 0.488603, 0.488603, 1.092548, 1.092548, 0.315392, 1.092548,
            0.546274};
        float[] out = new float[27];
        for (int i = 0; i < 9; i++) {
            for (int k = 0; k < 3; k++) {
                out[3 * i + k] = (float) (BAND_FACTOR[i] * constants[i] * coefficients[3 * i + k]);
            }
        }
        return out;
    }
}
