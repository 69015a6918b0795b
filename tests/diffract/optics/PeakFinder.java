package diffract.optics;

import diffract.optics.patches.Direction;

/** Finds diffraction peaks along the incidence plane, as the thesis' grating-equation evaluation did (001 ch. 5). */
final class PeakFinder {
    private static final int SAMPLES = 20001;

    private PeakFinder() {
    }

    /**
     * The mean over lambda of d = lambda / |t_peak - t_specular|, where t is the component of omega_r along the
     * incidence plane's azimuth phi_i and t_peak the strongest maximum outside the specular lobe (|s| > 1.5
     * texels from the specular lookup), refined by a parabola through log values (exact for a Gaussian peak).
     */
    static double meanPeriodFromFirstOrderUm(DiffractionBrdf brdf, double thetaIDeg, double phiIDeg,
                                              double lambdaMinNm, double lambdaMaxNm, double stepNm) {
        Direction wi = Direction.fromSphericalDeg(thetaIDeg, phiIDeg);
        double cos = Math.cos(Math.toRadians(phiIDeg));
        double sin = Math.sin(Math.toRadians(phiIDeg));
        double specular = -Math.sin(Math.toRadians(thetaIDeg));
        double extentUm = Math.abs(cos) > 0.5 ? brdf.spectrum().extentXUm() : brdf.spectrum().extentYUm();
        double sum = 0;
        int count = 0;
        for (double lambdaNm = lambdaMinNm; lambdaNm <= lambdaMaxNm + 1e-9; lambdaNm += stepNm) {
            double lambdaUm = lambdaNm * 1e-3;
            double[] t = new double[SAMPLES];
            double[] value = new double[SAMPLES];
            for (int k = 0; k < SAMPLES; k++) {
                t[k] = -0.9999 + 1.9998 * k / (SAMPLES - 1);
                value[k] = brdf.relative(wi, Direction.fromProjected(t[k] * cos, t[k] * sin), lambdaNm);
            }
            int best = -1;
            for (int k = 1; k < SAMPLES - 1; k++) {
                boolean outsideSpecularLobe = Math.abs(t[k] - specular) * extentUm / lambdaUm > 1.5;
                if (outsideSpecularLobe && value[k] >= value[k - 1] && value[k] > value[k + 1]
                        && (best < 0 || value[k] > value[best])) {
                    best = k;
                }
            }
            if (best < 0) {
                continue;
            }
            double peak = t[best] + parabolicOffset(value[best - 1], value[best], value[best + 1]) * (t[1] - t[0]);
            sum += lambdaUm / Math.abs(peak - specular);
            count++;
        }
        if (count == 0) {
            throw new IllegalStateException("no first-order peak found");
        }
        return sum / count;
    }

    private static double parabolicOffset(double left, double centre, double right) {
        if (left <= 0 || centre <= 0 || right <= 0) {
            return 0;
        }
        double a = Math.log(left);
        double b = Math.log(centre);
        double c = Math.log(right);
        double denominator = a - 2 * b + c;
        return denominator == 0 ? 0 : 0.5 * (a - c) / denominator;
    }
}
