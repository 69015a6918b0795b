package diffract.optics.rigorous;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The Fourier modal method of 2-D cells checked as a rigorous solver is checked: a flat cell is Fresnel's, a lossless
 * cell conserves energy in every mount (conical too), a cell whose rows are all the same is the 1-D solver's grating
 * (exactly for s polarised along the grooves, where both use Laurent's rule), reciprocity holds, orders leave where the
 * grating equation says in both directions, and the harmonics and the staircase converge (printed).
 */
class CellFourierModalMethodTest {
    private static final ComplexIndex KERATIN = ComplexIndex.KERATIN;

    /** A square pillar of side {@code side} (fraction of the cell) and height {@code depthUm}, on a grid. */
    static CellRelief pillar(double periodXUm, double periodYUm, int cols, int rows, int side, double depthUm) {
        double[] h = new double[cols * rows];
        for (int r = 0; r < side; r++) {
            for (int c = 0; c < side; c++) {
                h[r * cols + c] = depthUm;
            }
        }
        return new CellRelief(periodXUm, periodYUm, cols, rows, h);
    }

    /** A smooth bump, cos^2 of the distance from the cell's centre, of height {@code depthUm}. */
    static CellRelief bump(double periodXUm, double periodYUm, int cols, int rows, double depthUm) {
        double[] h = new double[cols * rows];
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                double x = (c + 0.5) / cols - 0.5;
                double y = (r + 0.5) / rows - 0.5;
                double d = Math.min(0.5, Math.hypot(x, y));
                double s = Math.cos(Math.PI * d);
                h[r * cols + c] = depthUm * s * s;
            }
        }
        return new CellRelief(periodXUm, periodYUm, cols, rows, h);
    }

    private static double[] direction(double thetaDeg, double phiDeg) {
        double t = Math.toRadians(thetaDeg);
        double p = Math.toRadians(phiDeg);
        return new double[] {Math.sin(t) * Math.cos(p), Math.sin(t) * Math.sin(p)};
    }

    @Test
    void aFlatCellIsFresnelsForBothPolarisationsAtEveryAngle() {
        for (ComplexIndex index : List.of(KERATIN, new ComplexIndex(1.5, 0.1))) {
            for (int theta = 0; theta <= 89; theta++) {
                double[] in = direction(theta, 17 * theta);
                CellEfficiencies e = CellFourierModalMethod.solve(Cell.flat(0.8, 0.9, index), 0.55, in[0], in[1], 2, 2);
                double[] exact = FourierModalMethodTest.fresnel(index, Math.toRadians(theta));
                int zero = e.index(0, 0);
                assertEquals(exact[0], e.reflectedS()[zero], 1e-9, "R_s of " + index + " at " + theta + " degrees");
                assertEquals(exact[1], e.reflectedP()[zero], 1e-9, "R_p of " + index + " at " + theta + " degrees");
                for (int i = 0; i < e.count(); i++) {
                    if (i != zero) {
                        assertEquals(0, e.reflectedS()[i] + e.reflectedP()[i], 1e-20, "a flat cell has no order "
                                + e.orderX(i) + ", " + e.orderY(i));
                    }
                }
                if (!index.absorbs()) {
                    assertEquals(1, e.energy()[0], 1e-9);
                    assertEquals(1, e.energy()[1], 1e-9);
                }
            }
        }
    }

    @Test
    void losslessCellsConserveEnergyInEveryMount() {
        List<Cell> cells = List.of(Cell.of(pillar(1.0, 1.2, 8, 8, 4, 0.3), 1, KERATIN),
                Cell.of(bump(1.1, 1.1, 12, 12, 0.25), 4, KERATIN));
        for (Cell cell : cells) {
            for (double[] angles : new double[][] {{0, 0}, {30, 0}, {30, 40}, {60, 120}}) {
                double[] in = direction(angles[0], angles[1]);
                CellEfficiencies e = CellFourierModalMethod.solve(cell, 0.45, in[0], in[1], 3, 3);
                String where = cell.slabs().size() + " slabs at " + angles[0] + ", " + angles[1] + " degrees";
                assertEquals(1, e.energy()[0], 1e-9, "R + T for s, " + where);
                assertEquals(1, e.energy()[1], 1e-9, "R + T for p, " + where);
                double diffracted = e.totalReflected() - e.reflected(0, 0);
                assertTrue(diffracted > 1e-4, "some light leaves in other orders, " + where + ": " + diffracted);
            }
        }
    }

    /**
     * A cell whose rows are all the same is a 1-D grating. At normal incidence s is polarised along the grooves (TE),
     * where the 1-D solver uses Laurent's rule as the cell does: the two agree to rounding. For p (TM) the 1-D solver
     * uses Li's inverse rule and the cell Laurent's: the difference is printed, and shrinks as M grows.
     */
    @Test
    void aCellOfEqualRowsIsTheOneDimensionalGrating() {
        int cols = 10;
        double periodUm = 1.3;
        double depthUm = 0.25;
        double[] h = new double[cols * 3];
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 4; c++) {
                h[r * cols + c] = depthUm;
            }
        }
        Cell cell = Cell.of(new CellRelief(periodUm, 0.9, cols, 3, h), 1, KERATIN);
        Grating grating = new Grating(periodUm, List.of(new Slab(depthUm, new double[] {0, 0.4})), KERATIN, KERATIN);
        for (int m : new int[] {5, 10, 20}) {
            OrderEfficiencies one = FourierModalMethod.solve(grating, 0.5, 0, 0, m);
            for (int maxY : new int[] {0, 1}) {
                CellEfficiencies two = CellFourierModalMethod.solve(cell, 0.5, 0, 0, m, maxY);
                double worstP = 0;
                for (int p = -m; p <= m; p++) {
                    int i = two.index(p, 0);
                    int j = one.index(p);
                    assertEquals(one.reflectedS()[j], two.reflectedS()[i], 1e-9, "R_s of order " + p + ", M " + m);
                    assertEquals(one.transmittedS()[j], two.transmittedS()[i], 1e-9, "T_s of order " + p);
                    worstP = Math.max(worstP, Math.abs(one.reflectedP()[j] - two.reflectedP()[i]));
                    for (int q = -maxY; q <= maxY; q++) {
                        if (q != 0) {
                            assertEquals(0, two.reflected(p, q), 1e-12, "a y-invariant cell has no order " + p + ", "
                                    + q);
                        }
                    }
                }
                if (maxY == 0) {
                    System.out.printf(Locale.ROOT, "equal rows, M = %d: R_p (Laurent) - R_p (Li) up to %.2e "
                            + "(R_p,0 = %.5f)%n", m, worstP, one.reflectedP()[one.index(0)]);
                }
            }
        }
    }

    /**
     * Reciprocity: order (p, q) of light from A leaves along B; light from -B sends its order (p, q) along -A with the
     * same unpolarised efficiency (R. Petit, Electromagnetic Theory of Gratings, 1980). The specular order's two solves
     * truncate mirror-image harmonic sets, so it holds to rounding; a diffracted order's sets are shifted by (p, q),
     * so it holds to the truncation's error, which shrinks with M (measured: 34 % at M = 3, 1.2 % at M = 6 on the
     * faintest orders of a pillar, Laurent's rule converging slowly).
     */
    @Test
    @Tag(diffract.jrtr.GlTestSupport.LONG_TAG) // a sweep over mounts: a long test
    void reciprocity() {
        Cell cell = Cell.of(pillar(1.0, 1.2, 8, 8, 3, 0.3), 1, KERATIN);
        double lambda = 0.5;
        double[] in = {0.3, 0.25};
        double[] worst = new double[2];
        int[] orders = {3, 5};
        for (int k = 0; k < 2; k++) {
            int m = orders[k];
            CellEfficiencies forward = CellFourierModalMethod.solve(cell, lambda, in[0], in[1], m, m);
            for (int p = -1; p <= 1; p++) {
                for (int q = -1; q <= 1; q++) {
                    int i = forward.index(p, q);
                    double a = forward.alpha()[i];
                    double b = forward.beta()[i];
                    if (a * a + b * b >= 1) {
                        continue;
                    }
                    CellEfficiencies back = CellFourierModalMethod.solve(cell, lambda, -a, -b, m, m);
                    double there = forward.reflected(p, q);
                    double here = back.reflected(p, q);
                    if (p == 0 && q == 0) {
                        assertEquals(there, here, 1e-9 * there, "the specular order, M = " + m);
                    } else {
                        worst[k] = Math.max(worst[k], Math.abs(there - here) / there);
                    }
                }
            }
            System.out.printf(Locale.ROOT, "reciprocity, M = %d: diffracted orders differ by up to %.2e%n", m,
                    worst[k]);
        }
        assertTrue(worst[1] < 0.5 * worst[0] && worst[1] < 0.1, "reciprocity converges with M: "
                + java.util.Arrays.toString(worst));
    }

    /**
     * Convergence in the harmonics and the staircase's layers, printed: the smooth bump's unpolarised specular and
     * first orders for M = 2..4 (4 layers) and L = 4, 8, 16 (M = 3), and the extrapolation from L / 2 and L
     * ({@link CellSolver}). The specular order moves by less than 2 % between the two finest of each.
     */
    @Test
    @Tag(diffract.jrtr.GlTestSupport.LONG_TAG) // a convergence sweep: a long test
    void theHarmonicsAndTheLayersConverge() {
        CellRelief bump = bump(1.1, 1.1, 12, 12, 0.25);
        double[] in = direction(20, 30);
        double[] specular = new double[3];
        for (int m = 2; m <= 4; m++) {
            CellEfficiencies e = CellFourierModalMethod.solve(Cell.of(bump, 4, KERATIN), 0.45, in[0], in[1], m, m);
            specular[m - 2] = e.reflected(0, 0);
            System.out.printf(Locale.ROOT, "harmonics M = %d (4 layers): R_00 %.6f R_10 %.6f R_01 %.6f R %.6f%n", m,
                    e.reflected(0, 0), e.reflected(1, 0), e.reflected(0, 1), e.totalReflected());
        }
        assertEquals(specular[2], specular[1], 0.02 * specular[2], "R_00 from M = 3 to 4");
        double[] layered = new double[3];
        for (int k = 0; k < 3; k++) {
            int layers = 4 << k;
            CellEfficiencies e = CellFourierModalMethod.solve(Cell.of(bump, layers, KERATIN), 0.45, in[0], in[1], 3, 3);
            CellEfficiencies x = CellSolver.solve(bump, KERATIN, 0.45, in[0], in[1], new Resolution(3, layers, true));
            layered[k] = e.reflected(0, 0);
            System.out.printf(Locale.ROOT, "layers L = %d (M = 3): R_00 %.6f R_10 %.6f, extrapolated from %d: R_00 "
                    + "%.6f R_10 %.6f%n", layers, e.reflected(0, 0), e.reflected(1, 0), layers / 2,
                    x.reflected(0, 0), x.reflected(1, 0));
        }
        assertEquals(layered[2], layered[1], 0.02 * layered[2], "R_00 from 8 to 16 layers");
    }

    /**
     * A slab of a 1.2 um Elaphe-like cell (16 x 16 samples) at 405 nm, 20 degrees, M = 4, slab 12 of 24: Hipparchus'
     * Schur iteration stalls there at a few ulps and converges at its default threshold ({@link ComplexEigen}'s
     * fallback); every eigenpair still passes the residual check, and the whole cell conserves energy to 1e-9.
     */
    @Test
    void aSlabWhoseSchurIterationStallsIsStillSolved() {
        diffract.optics.patches.HeightField f = diffract.optics.patches.SyntheticPatches.elapheLike(16, 8, 0.15, 0.3, 1)
                .meanSubtracted();
        CellRelief relief = new CellRelief(f.widthUm(), f.heightExtentUm(), f.cols(), f.rows(), f.heightsUm());
        int m = 4;
        double lambdaUm = 0.405;
        double alpha0 = -Math.sin(Math.toRadians(20));
        int n = (2 * m + 1) * (2 * m + 1);
        double[] alpha = new double[n];
        double[] beta = new double[n];
        for (int i = 0; i < n; i++) {
            alpha[i] = alpha0 + (i % (2 * m + 1) - m) * lambdaUm / relief.periodXUm();
            beta[i] = (i / (2 * m + 1) - m) * lambdaUm / relief.periodYUm();
        }
        CellSlab slab = CellStaircase.of(relief, 24).get(11);
        ComplexEigen eigen = ComplexEigen.of(CellModes.operators(slab.fourier(2 * m, 2 * m), KERATIN.permittivityRe(),
                0, m, m, alpha, beta)[2]);
        assertTrue(eigen.relaxed(), "the Schur iteration stalls at " + ComplexEigen.SCHUR_EPSILON);
        CellEfficiencies e = CellFourierModalMethod.solve(Cell.of(relief, 24, KERATIN), lambdaUm, alpha0, 0, m, m);
        assertEquals(1, e.energy()[0], 1e-9);
        assertEquals(1, e.energy()[1], 1e-9);
    }
}
