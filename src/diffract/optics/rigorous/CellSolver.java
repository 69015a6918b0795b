package diffract.optics.rigorous;

/**
 * The efficiencies of a 2-D cell at the {@link Resolution} asked, as {@link RigorousSolver} gives a 1-D relief's: the
 * Fourier modal method on its staircase ({@link CellFourierModalMethod}) and, where asked, the staircase's
 * extrapolation from L / 2 and L slabs by the same rule. The harmonics: {@link Resolution#maxOrder} along each period
 * (the 1-D default's choice per axis, or the asked M in both directions). The cell stands on a half-space of its own
 * material.
 */
public final class CellSolver {
    private CellSolver() {
    }

    /** M_x and M_y for light of {@code lambdaUm} on {@code relief}. */
    public static int[] maxOrders(CellRelief relief, double lambdaUm, Resolution resolution) {
        return new int[] {resolution.maxOrder(relief.periodXUm(), lambdaUm),
                resolution.maxOrder(relief.periodYUm(), lambdaUm)};
    }

    /** Orders (p, q) of light of {@code lambdaUm} travelling along (alpha0, beta0, kappa_0) onto {@code relief}. */
    public static CellEfficiencies solve(CellRelief relief, ComplexIndex material, double lambdaUm, double alpha0,
                                         double beta0, Resolution resolution) {
        int[] m = maxOrders(relief, lambdaUm, resolution);
        CellEfficiencies fine = CellFourierModalMethod.solve(Cell.of(relief, resolution.layers(), material), lambdaUm,
                alpha0, beta0, m[0], m[1]);
        if (!resolution.extrapolate() || relief.depthUm() == 0) {
            return fine;
        }
        CellEfficiencies coarse = CellFourierModalMethod.solve(Cell.of(relief, resolution.layers() / 2, material),
                lambdaUm, alpha0, beta0, m[0], m[1]);
        double factor = 1 / (Math.pow(2, Resolution.STAIRCASE_ORDER) - 1);
        return new CellEfficiencies(fine.lambdaUm(), m[0], m[1], fine.alpha(), fine.beta(),
                RigorousSolver.extrapolated(fine.reflectedS(), coarse.reflectedS(), factor),
                RigorousSolver.extrapolated(fine.reflectedP(), coarse.reflectedP(), factor),
                RigorousSolver.extrapolated(fine.transmittedS(), coarse.transmittedS(), factor),
                RigorousSolver.extrapolated(fine.transmittedP(), coarse.transmittedP(), factor));
    }
}
