package diffract.optics.rigorous;

import org.ejml.data.ZMatrixRMaj;

/**
 * Rigorous coupled-wave analysis (the Fourier modal method) of a 1-D grating: Maxwell's equations solved for a plane
 * wave of one wavelength, the relief a staircase of slabs ({@link Staircase}), each slab's field a sum of its
 * eigenmodes on 2M + 1 Fourier harmonics ({@link Modes}, with Li's factorisation rules), the slabs joined by
 * scattering matrices ({@link ScatteringMatrix}). The result is every reflected and transmitted order's efficiency
 * for s- and p-polarised light ({@link OrderEfficiencies}), from any direction, in the plane of the grating vector
 * or out of it (conical incidence).
 *
 * <p>The grating's frame: x across the grooves (the period), y along them, zeta down into the material. Air above,
 * the substrate below. The incident plane wave's propagation direction is (alpha_0, beta, kappa_0) with
 * kappa_0 = sqrt(1 - alpha_0^2 - beta^2) &gt; 0; s is the polarisation perpendicular to the plane of incidence
 * ((-beta, alpha_0, 0), along the grooves at normal incidence), p the one in it.
 *
 * <p>Truncation: the harmonics m = -M..M; the efficiencies converge as M grows (Li's rules make TM converge about as
 * fast as TE) and as the staircase's layers do; {@link Convergence} reports both.
 */
public final class FourierModalMethod {
    /** An order this close to grazing (|kappa^2| below it) counts as at a Rayleigh anomaly. */
    static final double ANOMALY = 1e-10;
    /** The relative change of the wavelength that moves an order off grazing. */
    static final double ANOMALY_SHIFT = 1e-9;

    private FourierModalMethod() {
    }

    /** Whether some harmonic grazes the air or a lossless substrate (kappa^2 = 0 there). */
    static boolean atRayleighAnomaly(Grating grating, double lambdaUm, double alpha0, double beta, int maxOrder) {
        ComplexIndex substrate = grating.substrate();
        for (int m = -maxOrder; m <= maxOrder; m++) {
            double a = alpha0 + m * lambdaUm / grating.periodUm();
            double k2 = a * a + beta * beta;
            if (Math.abs(1 - k2) < ANOMALY
                    || (!substrate.absorbs() && Math.abs(substrate.permittivityRe() - k2) < ANOMALY)) {
                return true;
            }
        }
        return false;
    }

    /**
     * The efficiencies of orders -M..M for light of {@code lambdaUm} travelling along (alpha0, beta, kappa_0).
     *
     * @param maxOrder M: the highest harmonic kept (2M + 1 in all)
     */
    public static OrderEfficiencies solve(Grating grating, double lambdaUm, double alpha0, double beta, int maxOrder) {
        if (!(lambdaUm > 0)) {
            throw new IllegalArgumentException("the wavelength must be > 0 um, got " + lambdaUm);
        }
        if (maxOrder < 0) {
            throw new IllegalArgumentException("the highest harmonic must be >= 0, got " + maxOrder);
        }
        double incidentKappa2 = 1 - alpha0 * alpha0 - beta * beta;
        if (!(incidentKappa2 > 0)) {
            throw new IllegalArgumentException("the incident wave must travel down into the grating: alpha^2 + beta^2 "
                    + "< 1, got " + (alpha0 * alpha0 + beta * beta));
        }
        if (atRayleighAnomaly(grating, lambdaUm, alpha0, beta, maxOrder)) {
            // an order exactly at grazing has no propagation constant; a wavelength 1e-9 longer moves it off, and the
            // efficiencies, continuous there (with a square-root kink), move by about 3e-5 of themselves at most
            return solve(grating, lambdaUm * (1 + ANOMALY_SHIFT), alpha0, beta, maxOrder);
        }
        int n = 2 * maxOrder + 1;
        double[] alpha = new double[n];
        double widest = 0;
        for (int i = 0; i < n; i++) {
            alpha[i] = alpha0 + (i - maxOrder) * lambdaUm / grating.periodUm();
            widest = Math.max(widest, alpha[i] * alpha[i] + beta * beta);
        }
        double k0 = 2 * Math.PI / lambdaUm;
        ComplexIndex material = grating.material();
        ComplexIndex substrate = grating.substrate();
        Modes air = Modes.homogeneous(1, 0, alpha, beta);
        // a gap in which every harmonic propagates (kappa^2 >= 1): no zero propagation constant, whatever the orders
        Modes gap = Modes.homogeneous(2 + widest, 0, alpha, beta);
        ScatteringMatrix s = ScatteringMatrix.reflectionSide(air, gap);
        for (Slab slab : grating.slabs()) {
            Modes modes;
            if (slab.uniform()) {
                modes = slab.fill() > 0 ? Modes.homogeneous(material.permittivityRe(), material.permittivityIm(), alpha,
                        beta) : air;
            } else {
                modes = Modes.slab(slab, material.permittivityRe(), material.permittivityIm(), alpha, beta);
            }
            s = s.star(ScatteringMatrix.layer(modes, gap, k0 * slab.thicknessUm()));
        }
        Modes below = Modes.homogeneous(substrate.permittivityRe(), substrate.permittivityIm(), alpha, beta);
        s = s.star(ScatteringMatrix.transmissionSide(below, gap));

        double kappa0 = Math.sqrt(incidentKappa2);
        double[][] reflected = new double[2][];
        double[][] transmitted = new double[2][];
        double[][] polarisations = polarisations(alpha0, beta, kappa0);
        double[] betas = new double[n];
        java.util.Arrays.fill(betas, beta);
        for (int p = 0; p < 2; p++) {
            double[] source = new double[4 * n];
            source[2 * maxOrder] = polarisations[p][0];
            source[2 * (n + maxOrder)] = polarisations[p][1];
            reflected[p] = efficiencies(s.s11(), source, air.kappa(), alpha, betas, kappa0, 1);
            transmitted[p] = efficiencies(s.s21(), source, below.kappa(), alpha, betas, kappa0, -1);
        }
        return new OrderEfficiencies(lambdaUm, -maxOrder, alpha, beta, reflected[0], reflected[1], transmitted[0],
                transmitted[1]);
    }

    /**
     * The incident wave's tangential electric field for s and for p light, {{s_x, s_y}, {p_x, p_y}}: s = (-beta,
     * alpha0, 0) / rho (along the grooves, y, at normal incidence), p = k x s, for the wave along (alpha0, beta,
     * kappa0).
     */
    static double[][] polarisations(double alpha0, double beta, double kappa0) {
        double rho = Math.hypot(alpha0, beta);
        double sx = rho > 1e-12 ? -beta / rho : 0;
        double sy = rho > 1e-12 ? alpha0 / rho : 1;
        return new double[][] {{sx, sy}, {-kappa0 * sy, kappa0 * sx}};
    }

    /**
     * Each order's share of the incident power: the order's field e = S source (tangential, W = I in a homogeneous
     * region), its normal component from div E = 0 ({@code up}: +1 for a wave going up, -1 down), and the power
     * flux Re(kappa_m) |E_m|^2 over the incident kappa_0 |E_0|^2 (|E_0| = 1). Harmonic m travels along
     * (alpha_m, beta_m): a 1-D grating's beta_m are all the same, a 2-D cell's are not.
     */
    static double[] efficiencies(ZMatrixRMaj s, double[] source, double[] kappa, double[] alpha, double[] beta,
                                         double kappa0, int up) {
        int n = alpha.length;
        double[] field = new double[4 * n];
        int size = 2 * n;
        for (int i = 0; i < size; i++) {
            double re = 0;
            double im = 0;
            for (int j = 0; j < size; j++) {
                double sr = source[2 * j];
                if (sr == 0) {
                    continue;
                }
                re += s.getReal(i, j) * sr;
                im += s.getImag(i, j) * sr;
            }
            field[2 * i] = re;
            field[2 * i + 1] = im;
        }
        double[] out = new double[n];
        for (int m = 0; m < n; m++) {
            double kr = kappa[2 * m];
            double ki = kappa[2 * m + 1];
            if (!(kr > 0) || ki > 1e-9 * kr) {
                continue; // evanescent (or absorbed on the way out): no power leaves
            }
            double exr = field[2 * m];
            double exi = field[2 * m + 1];
            double eyr = field[2 * (n + m)];
            double eyi = field[2 * (n + m) + 1];
            // E_z = up (alpha E_x + beta E_y) / kappa
            double nr = alpha[m] * exr + beta[m] * eyr;
            double ni = alpha[m] * exi + beta[m] * eyi;
            double[] inv = Modes.inverse(kr, ki);
            double ezr = up * (nr * inv[0] - ni * inv[1]);
            double ezi = up * (nr * inv[1] + ni * inv[0]);
            double e2 = exr * exr + exi * exi + eyr * eyr + eyi * eyi + ezr * ezr + ezi * ezi;
            out[m] = kr * e2 / kappa0;
        }
        return out;
    }
}
