package diffract.optics.rigorous;

import java.util.HashMap;
import java.util.Map;

/**
 * The Fourier modal method of a 2-D (crossed) cell: {@link FourierModalMethod} with harmonics (p, q) in both
 * directions. The relief is a staircase of {@link CellSlab}s, each slab's field a sum of its eigenmodes
 * ({@link CellModes}, Laurent's rule), the slabs joined by the same scattering matrices ({@link ScatteringMatrix}); the
 * result is every reflected and transmitted order's efficiency for s- and p-polarised light ({@link CellEfficiencies}).
 *
 * <p>The frame and the polarisations are {@link FourierModalMethod}'s: the incident wave travels along
 * (alpha_0, beta_0, kappa_0), s is (-beta_0, alpha_0, 0) normalised (y at normal incidence), p = k x s.
 *
 * <p>Cost: per distinct slab one eigenproblem of 2N complex unknowns (decomposed as a real matrix of 4N), about
 * (2N)^3 operations for each of the scattering matrices' products; slabs with the same mask and thickness (a cell of
 * few heights) share one solve.
 */
public final class CellFourierModalMethod {
    private CellFourierModalMethod() {
    }

    /** Whether some harmonic grazes the air or a lossless substrate (kappa^2 = 0 there). */
    static boolean atRayleighAnomaly(Cell cell, double lambdaUm, double alpha0, double beta0, int maxX, int maxY) {
        ComplexIndex substrate = cell.substrate();
        for (int q = -maxY; q <= maxY; q++) {
            double b = beta0 + q * lambdaUm / cell.periodYUm();
            for (int p = -maxX; p <= maxX; p++) {
                double a = alpha0 + p * lambdaUm / cell.periodXUm();
                double k2 = a * a + b * b;
                if (Math.abs(1 - k2) < FourierModalMethod.ANOMALY || (!substrate.absorbs()
                        && Math.abs(substrate.permittivityRe() - k2) < FourierModalMethod.ANOMALY)) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * The efficiencies of orders |p| &lt;= maxX, |q| &lt;= maxY for light of {@code lambdaUm} travelling along
     * (alpha0, beta0, kappa_0).
     */
    public static CellEfficiencies solve(Cell cell, double lambdaUm, double alpha0, double beta0, int maxX,
                                         int maxY) {
        if (!(lambdaUm > 0)) {
            throw new IllegalArgumentException("the wavelength must be > 0 um, got " + lambdaUm);
        }
        if (maxX < 0 || maxY < 0) {
            throw new IllegalArgumentException("the highest harmonics must be >= 0, got " + maxX + ", " + maxY);
        }
        double incidentKappa2 = 1 - alpha0 * alpha0 - beta0 * beta0;
        if (!(incidentKappa2 > 0)) {
            throw new IllegalArgumentException("the incident wave must travel down into the cell: alpha^2 + beta^2 "
                    + "< 1, got " + (alpha0 * alpha0 + beta0 * beta0));
        }
        if (atRayleighAnomaly(cell, lambdaUm, alpha0, beta0, maxX, maxY)) {
            // as in 1-D: a wavelength 1e-9 longer moves a grazing order off grazing
            return solve(cell, lambdaUm * (1 + FourierModalMethod.ANOMALY_SHIFT), alpha0, beta0, maxX, maxY);
        }
        int nx = 2 * maxX + 1;
        int n = nx * (2 * maxY + 1);
        double[] alpha = new double[n];
        double[] beta = new double[n];
        double widest = 0;
        for (int i = 0; i < n; i++) {
            alpha[i] = alpha0 + (i % nx - maxX) * lambdaUm / cell.periodXUm();
            beta[i] = beta0 + (i / nx - maxY) * lambdaUm / cell.periodYUm();
            widest = Math.max(widest, alpha[i] * alpha[i] + beta[i] * beta[i]);
        }
        double k0 = 2 * Math.PI / lambdaUm;
        ComplexIndex material = cell.material();
        ComplexIndex substrate = cell.substrate();
        Modes air = Modes.homogeneous(1, 0, alpha, beta);
        Modes gap = Modes.homogeneous(2 + widest, 0, alpha, beta);
        ScatteringMatrix s = ScatteringMatrix.reflectionSide(air, gap);
        Map<CellSlab, ScatteringMatrix> solved = new HashMap<>();
        for (CellSlab slab : cell.slabs()) {
            ScatteringMatrix layer = solved.get(slab);
            if (layer == null) {
                Modes modes;
                if (slab.uniform()) {
                    modes = slab.fill() > 0 ? Modes.homogeneous(material.permittivityRe(), material.permittivityIm(),
                            alpha, beta) : air;
                } else {
                    modes = CellModes.of(slab.fourier(2 * maxX, 2 * maxY), material.permittivityRe(),
                            material.permittivityIm(), maxX, maxY, alpha, beta);
                }
                layer = ScatteringMatrix.layer(modes, gap, k0 * slab.thicknessUm());
                solved.put(slab, layer);
            }
            s = s.star(layer);
        }
        Modes below = Modes.homogeneous(substrate.permittivityRe(), substrate.permittivityIm(), alpha, beta);
        s = s.star(ScatteringMatrix.transmissionSide(below, gap));

        double kappa0 = Math.sqrt(incidentKappa2);
        double[][] reflected = new double[2][];
        double[][] transmitted = new double[2][];
        double[][] polarisations = FourierModalMethod.polarisations(alpha0, beta0, kappa0);
        int zero = maxY * nx + maxX;
        for (int pol = 0; pol < 2; pol++) {
            double[] source = new double[4 * n];
            source[2 * zero] = polarisations[pol][0];
            source[2 * (n + zero)] = polarisations[pol][1];
            reflected[pol] = FourierModalMethod.efficiencies(s.s11(), source, air.kappa(), alpha, beta, kappa0, 1);
            transmitted[pol] = FourierModalMethod.efficiencies(s.s21(), source, below.kappa(), alpha, beta, kappa0,
                    -1);
        }
        return new CellEfficiencies(lambdaUm, maxX, maxY, alpha, beta, reflected[0], reflected[1], transmitted[0],
                transmitted[1]);
    }
}
