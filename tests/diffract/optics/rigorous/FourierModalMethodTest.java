package diffract.optics.rigorous;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The Fourier modal method checked as a rigorous solver is checked: a flat interface is Fresnel's, a lossless grating
 * conserves energy, an absorbing one does not, reciprocity holds, orders leave where the grating equation says, the
 * harmonics and the staircase converge, and a binary grating's staircase is exact with one slab.
 */
class FourierModalMethodTest {
    private static final ComplexIndex KERATIN = ComplexIndex.KERATIN;

    /** |r_s|^2 and |r_p|^2 of a flat interface from air to index N = n + i k at incidence angle theta (exact). */
    static double[] fresnel(ComplexIndex index, double thetaRad) {
        double c = Math.cos(thetaRad);
        double s2 = Math.sin(thetaRad) * Math.sin(thetaRad);
        // cos theta_t N = sqrt(N^2 - sin^2): the outgoing branch
        double[] root = Modes.outgoing(index.permittivityRe() - s2, index.permittivityIm());
        double er = index.permittivityRe();
        double ei = index.permittivityIm();
        // r_s = (c - root) / (c + root)
        double rs = abs2(c - root[0], -root[1]) / abs2(c + root[0], root[1]);
        // r_p = (eps c - root) / (eps c + root)
        double rp = abs2(er * c - root[0], ei * c - root[1]) / abs2(er * c + root[0], ei * c + root[1]);
        return new double[] {rs, rp};
    }

    private static double abs2(double re, double im) {
        return re * re + im * im;
    }

    @Test
    void aFlatInterfaceIsFresnelsForBothPolarisationsAtEveryAngle() {
        for (ComplexIndex index : List.of(KERATIN, new ComplexIndex(1.5, 0.1), new ComplexIndex(2.4, 0))) {
            for (int theta = 0; theta <= 89; theta += 1) {
                double t = Math.toRadians(theta);
                double phi = Math.toRadians(17 * theta);
                OrderEfficiencies e = FourierModalMethod.solve(Grating.flat(0.8, index), 0.55,
                        Math.sin(t) * Math.cos(phi), Math.sin(t) * Math.sin(phi), 4);
                double[] exact = fresnel(index, t);
                int zero = e.index(0);
                assertEquals(exact[0], e.reflectedS()[zero], 1e-12, "R_s of " + index + " at " + theta + " degrees");
                assertEquals(exact[1], e.reflectedP()[zero], 1e-12, "R_p of " + index + " at " + theta + " degrees");
                for (int m = -4; m <= 4; m++) {
                    if (m != 0) {
                        assertEquals(0, e.reflected(m), 1e-20, "a flat interface has no order " + m);
                    }
                }
                if (!index.absorbs()) {
                    assertEquals(1, e.energy()[0], 1e-12);
                    assertEquals(1, e.energy()[1], 1e-12);
                }
            }
        }
    }

    @Test
    @Tag(diffract.jrtr.GlTestSupport.LONG_TAG) // a sweep over mounts: a long test
    void losslessGratingsConserveEnergyInEveryMount() {
        List<Profile> profiles = List.of(Profile.sinusoid(1.0, 0.3), Profile.sinusoid(0.65, 0.1),
                Profile.triangle(2.5, 0.4, 0.9), Profile.triangle(1.144, 0.3, 0.7));
        for (Profile p : profiles) {
            for (double[] angles : new double[][] {{0, 0}, {30, 0}, {60, 0}, {30, 40}, {75, 120}}) {
                double t = Math.toRadians(angles[0]);
                double phi = Math.toRadians(angles[1]);
                OrderEfficiencies e = FourierModalMethod.solve(Grating.of(p, 12, KERATIN), 0.45,
                        Math.sin(t) * Math.cos(phi), Math.sin(t) * Math.sin(phi), 25);
                String where = p.description() + " at " + angles[0] + ", " + angles[1] + " degrees";
                assertEquals(1, e.energy()[0], 1e-9, "R + T for s, " + where);
                assertEquals(1, e.energy()[1], 1e-9, "R + T for p, " + where);
                assertTrue(e.totalReflected() > 0.01, "some light is reflected, " + where);
            }
        }
    }

    @Test
    void anAbsorbingGratingReflectsAndTransmitsLess() {
        Profile p = Profile.sinusoid(1.0, 0.3);
        OrderEfficiencies lossless = FourierModalMethod.solve(Grating.of(p, 12, KERATIN), 0.5, 0.3, 0, 20);
        OrderEfficiencies absorbing = FourierModalMethod.solve(Grating.of(p, 12, new ComplexIndex(1.56, 0.3)), 0.5,
                0.3, 0, 20);
        assertEquals(1, lossless.energy()[0], 1e-9);
        // into an absorbing half-space nothing is transmitted to infinity; the reflection changes but stays < 1
        assertTrue(absorbing.totalReflected() < 1 && absorbing.totalReflected() > 0.01);
        assertEquals(0, absorbing.totalTransmitted(), 0);
    }

    /**
     * Order m of light along (alpha, beta) equals order m of light sent back along order m's direction (and, in the
     * plane of the grating vector, for each polarisation alone), to the truncation's error: 2e-5 of the order at M = 40
     * unpolarised, 1e-4 for p, falling as M grows
     */
    @Test
    @Tag(diffract.jrtr.GlTestSupport.LONG_TAG) // a sweep over mounts: a long test
    void reciprocity() {
        Grating g = Grating.of(Profile.triangle(1.3, 0.35, 0.8), 10, KERATIN);
        double lambda = 0.5;
        for (double[] in : new double[][] {{0.2, 0}, {-0.45, 0}, {0.3, 0.25}}) {
            OrderEfficiencies forward = FourierModalMethod.solve(g, lambda, in[0], in[1], 40);
            for (int m = -3; m <= 3; m++) {
                double alphaM = in[0] + m * lambda / g.periodUm();
                if (alphaM * alphaM + in[1] * in[1] >= 1) {
                    continue;
                }
                OrderEfficiencies back = FourierModalMethod.solve(g, lambda, -alphaM, -in[1], 40);
                double there = forward.reflected(m);
                // the two directions truncate mirror-image harmonic sets: they agree to the truncation's error
                assertEquals(there, back.reflected(m), 1e-9 + 1e-4 * there, "order " + m + " from " + in[0] + ", "
                        + in[1]);
                if (in[1] == 0) {
                    // in the plane of the grating vector the polarisations do not mix: each is reciprocal alone
                    // (TM converges slowest: 1e-4 of the order at M = 40)
                    int i = forward.index(m);
                    double s = forward.reflectedS()[i];
                    double p = forward.reflectedP()[i];
                    assertEquals(s, back.reflectedS()[back.index(m)], 1e-9 + 5e-4 * s, "s, order " + m);
                    assertEquals(p, back.reflectedP()[back.index(m)], 1e-9 + 5e-4 * p, "p, order " + m);
                }
            }
        }
    }

    @Test
    void ordersLeaveAtTheGratingEquation() {
        double period = 1.7;
        double lambda = 0.61;
        double alpha0 = Math.sin(Math.toRadians(25));
        OrderEfficiencies e = FourierModalMethod.solve(Grating.of(Profile.sinusoid(period, 0.2), 8, KERATIN), lambda,
                alpha0, 0.1, 10);
        for (int m = -10; m <= 10; m++) {
            assertEquals(alpha0 + m * lambda / period, e.alpha()[e.index(m)], 1e-15);
            boolean propagates = Math.pow(alpha0 + m * lambda / period, 2) + 0.01 < 1;
            if (!propagates) {
                assertEquals(0, e.reflected(m), 0, "evanescent order " + m + " carries nothing");
            }
        }
        assertTrue(e.reflected(-1) > 1e-3 && e.reflected(1) > 1e-3);
    }

    @Test
    void aBinaryGratingsStaircaseIsExactWithOneSlab() {
        // a rectangular relief: every slab is the same, so 1 slab of the full height equals 7 thinner ones
        Profile binary = new Profile(1.0, 0.25, t -> t > 0.3 && t < 0.75 ? 0.25 : 0, "binary");
        OrderEfficiencies one = FourierModalMethod.solve(Grating.of(binary, 1, KERATIN), 0.52, 0.2, 0.1, 30);
        OrderEfficiencies seven = FourierModalMethod.solve(Grating.of(binary, 7, KERATIN), 0.52, 0.2, 0.1, 30);
        for (int m = -3; m <= 3; m++) {
            assertEquals(one.reflected(m), seven.reflected(m), 1e-11, "order " + m);
        }
        assertEquals(0.45, Grating.of(binary, 1, KERATIN).slabs().get(0).fill(), 1e-12);
    }

    @Test
    @Tag(diffract.jrtr.GlTestSupport.LONG_TAG) // a convergence sweep: a long test
    void theHarmonicsAndTheStaircaseConverge() {
        Profile p = Profile.sinusoid(1.0, 0.3);
        double alpha0 = 0.5;
        double[] m10 = efficiencies(p, 20, 10, alpha0);
        double[] m30 = efficiencies(p, 20, 30, alpha0);
        double[] m40 = efficiencies(p, 20, 40, alpha0);
        for (int i = 0; i < m10.length; i++) {
            // 21 harmonics are within 1 % of 81, 61 within 0.2 %
            assertEquals(m40[i], m10[i], 0.01 * m40[i] + 1e-5, "order " + (i - 3) + " with M = 10");
            assertEquals(m40[i], m30[i], 0.002 * m40[i] + 1e-6, "order " + (i - 3) + " with M = 30");
        }
        // the staircase: each doubling of the slabs changes the orders less than half as much as the one before
        double[] l10 = efficiencies(p, 10, 20, alpha0);
        double[] l20 = efficiencies(p, 20, 20, alpha0);
        double[] l40 = efficiencies(p, 40, 20, alpha0);
        int checked = 0;
        for (int i = 0; i < l10.length; i++) {
            double first = Math.abs(l20[i] - l10[i]);
            double second = Math.abs(l40[i] - l20[i]);
            if (first > 1e-5) {
                assertTrue(second < 0.5 * first, "order " + (i - 3) + ": " + first + " then " + second);
                checked++;
            }
        }
        assertTrue(checked >= 2, "orders checked: " + checked);
    }

    /** Unpolarised efficiencies of orders -3..3 with L slabs and M harmonics. */
    private static double[] efficiencies(Profile p, int layers, int maxOrder, double alpha0) {
        OrderEfficiencies e = FourierModalMethod.solve(Grating.of(p, layers, KERATIN), 0.55, alpha0, 0, maxOrder);
        double[] out = new double[7];
        for (int m = -3; m <= 3; m++) {
            out[m + 3] = e.reflected(m);
        }
        return out;
    }

    @Test
    void anOrderExactlyAtGrazingIsSolvedJustPastIt() {
        // alpha_2 = 0.5 + 2 * 0.625 / 2.5 = 1: order 2 grazes the surface at 625 nm
        Grating g = Grating.of(Profile.sinusoid(2.5, 0.2), 8, KERATIN);
        OrderEfficiencies at = FourierModalMethod.solve(g, 0.625, 0.5, 0, 20);
        OrderEfficiencies near = FourierModalMethod.solve(g, 0.625 * (1 + 1e-6), 0.5, 0, 20);
        assertEquals(1, at.energy()[0], 1e-9);
        for (int m = -6; m <= 1; m++) {
            assertEquals(near.reflected(m), at.reflected(m), 2e-3 * near.reflected(m) + 1e-9, "order " + m);
        }
    }
}
