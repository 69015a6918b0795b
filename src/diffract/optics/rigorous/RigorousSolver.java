package diffract.optics.rigorous;

/**
 * The efficiencies of a 1-D relief at the {@link Resolution} asked: the Fourier modal method on its staircase, and
 * where asked the staircase's extrapolation (L / 2 and L slabs). The relief stands on a half-space of its own
 * material.
 */
public final class RigorousSolver {
    private RigorousSolver() {
    }

    /** Orders -M..M of light of {@code lambdaUm} travelling along (alpha0, beta, kappa_0) onto {@code profile}. */
    public static OrderEfficiencies solve(Profile profile, ComplexIndex material, double lambdaUm, double alpha0,
                                          double beta, Resolution resolution) {
        int m = resolution.maxOrder(profile.periodUm(), lambdaUm);
        OrderEfficiencies fine = FourierModalMethod.solve(Grating.of(profile, resolution.layers(), material), lambdaUm,
                alpha0, beta, m);
        if (!resolution.extrapolate() || profile.depthUm() == 0) {
            return fine;
        }
        OrderEfficiencies coarse = FourierModalMethod.solve(Grating.of(profile, resolution.layers() / 2, material),
                lambdaUm, alpha0, beta, m);
        double factor = 1 / (Math.pow(2, Resolution.STAIRCASE_ORDER) - 1);
        return new OrderEfficiencies(lambdaUm, fine.firstOrder(), fine.alpha(), fine.beta(),
                extrapolated(fine.reflectedS(), coarse.reflectedS(), factor),
                extrapolated(fine.reflectedP(), coarse.reflectedP(), factor),
                extrapolated(fine.transmittedS(), coarse.transmittedS(), factor),
                extrapolated(fine.transmittedP(), coarse.transmittedP(), factor));
    }

    /** fine + (fine - coarse) factor, kept &gt;= 0 (an order that is nearly dark may not turn negative). */
    static double[] extrapolated(double[] fine, double[] coarse, double factor) {
        double[] out = new double[fine.length];
        for (int i = 0; i < fine.length; i++) {
            out[i] = Math.max(0, fine[i] + (fine[i] - coarse[i]) * factor);
        }
        return out;
    }
}
