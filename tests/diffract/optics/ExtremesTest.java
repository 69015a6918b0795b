package diffract.optics;

import diffract.colour.Xyz;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.spectra.PhaseCentredTerms;
import diffract.optics.spectra.PhaseCentres;
import diffract.optics.spectra.TaylorSincSpectrum;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.windows.WindowPlacement;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Numerical stability of the CPU BRDFs at the extremes: grazing light and view up to 89.9 degrees,
 * w -> 0, the exact specular direction, the ends of the spectrum, heights from 0.01 to 2 um, a constant field,
 * N = 0 and N = 100, 1 x 1, odd and non-square patches. Every value must be finite and non-negative.
 */
class ExtremesTest {
    private static final double[] THETAS_DEG = {0, 30, 60, 85, 89.9};
    private static final double[] PHIS_DEG = {0, 37, 90, 180, 251};

    private static List<Direction> directions() {
        List<Direction> out = new ArrayList<>();
        for (double theta : THETAS_DEG) {
            for (double phi : PHIS_DEG) {
                out.add(Direction.fromSphericalDeg(theta, phi));
            }
        }
        return out;
    }

    private static void assertSane(double value, String where) {
        assertTrue(Double.isFinite(value), where + ": " + value);
        assertTrue(value >= 0, where + ": negative " + value);
    }

    private static void checkAllVariants(HeightField patch, int highestOrder, String name) {
        TaylorTerms terms = TaylorTermComputer.compute(patch, highestOrder, Reporter.SILENT);
        for (Variant variant : Variant.values()) {
            // the rigorous method solves 1-D patches, one light direction at a time: RigorousExtremesTest
            if (!variant.runsOnCpu() || variant == Variant.RIGOROUS) {
                continue;
            }
            DiffractionBrdf brdf = DiffractionBrdf.create(
                    BrdfSettings.thesis(variant).with(b -> b.highestOrder(highestOrder)).with(b -> b.lambdaStepNm(50)), patch, terms);
            for (Direction wi : directions()) {
                List<Direction> views = new ArrayList<>(directions());
                views.add(wi.specular()); // exactly specular: (u, v) = 0
                views.add(new Direction(-wi.x(), -wi.y(), wi.z()));
                for (Direction wr : views) {
                    String where = name + " " + variant + " wi " + wi + " wr " + wr;
                    Xyz xyz = brdf.xyz(wi, wr);
                    assertSane(xyz.y(), where + " Y");
                    assertTrue(Double.isFinite(xyz.x()) && Double.isFinite(xyz.z()), where + " XZ " + xyz);
                    for (double lambda : new double[] {380, 780}) {
                        assertSane(brdf.relative(wi, wr, lambda), where + " at " + lambda + " nm");
                    }
                }
            }
        }
    }

    @Test
    void heightsFromTenNanometresToTwoMicrometres() {
        for (double maxH : new double[] {0.01, 0.5, 2.0}) {
            HeightField patch = NaiveDft.randomPatch(12, 16, maxH, 0.1, 17);
            // x = k |w| max|h| reaches ~33 at 2 um: N = 100 keeps the series' remainder small there
            checkAllVariants(patch, maxH > 1 ? 100 : 30, "random maxH " + maxH);
        }
    }

    @Test
    void tallPatchesOnThePhaseCentredPath() {
        // The centred expansion at the same angles, the exact specular direction and both spectrum ends
        for (double maxH : new double[] {0.5, 2.0}) {
            HeightField patch = NaiveDft.randomPatch(12, 16, 2 * maxH, 0.1, 17);
            PhaseCentredTerms centred = TaylorTermComputer.computeCentred(patch,
                    PhaseCentres.forPatch(patch.maxAbsHeightUm(), 380), Reporter.SILENT);
            for (Variant variant : new Variant[] {Variant.FLSS, Variant.NMM, Variant.PQ}) {
                DiffractionBrdf brdf = DiffractionBrdf.createPhaseCentred(
                        BrdfSettings.thesis(variant).with(b -> b.lambdaStepNm(50)), centred);
                for (Direction wi : directions()) {
                    List<Direction> views = new ArrayList<>(directions());
                    views.add(wi.specular());
                    for (Direction wr : views) {
                        String where = "centred maxH " + maxH + " " + variant + " wi " + wi + " wr " + wr;
                        assertSane(brdf.xyz(wi, wr).y(), where + " Y");
                        for (double lambda : new double[] {380, 780}) {
                            assertSane(brdf.relative(wi, wr, lambda), where + " at " + lambda + " nm");
                        }
                    }
                }
            }
        }
    }

    @Test
    void constantOddNonSquareAndSinglePixelPatches() {
        checkAllVariants(HeightField.of(5, 7, filled(35, 0.3), 0.1).meanSubtracted(), 5, "constant 5x7");
        checkAllVariants(NaiveDft.randomPatch(7, 3, 0.2, 0.08, 3), 10, "random 7x3");
        checkAllVariants(HeightField.of(1, 1, new double[] {0.4}, 0.1).meanSubtracted(), 3, "1x1");
        checkAllVariants(NaiveDft.randomPatch(1, 9, 0.2, 0.1, 4), 10, "1x9");
    }

    @Test
    void a4096By4096PatchPrecomputesAndEvaluates() {
        int size = 4096;
        double[] h = new double[size * size];
        for (int r = 0; r < size; r++) {
            for (int c = 0; c < size; c++) {
                h[r * size + c] = 0.1 * Math.sin(2 * Math.PI * c / 16.0) + 0.05 * Math.cos(2 * Math.PI * r / 64.0);
            }
        }
        HeightField patch = HeightField.of(size, size, h, 0.05).meanSubtracted();
        TaylorTerms terms = TaylorTermComputer.compute(patch, 1, Reporter.SILENT);
        assertEquals(1.0, terms.re(0, size / 2, size / 2), 1e-6, "DC of term 0");
        DiffractionBrdf brdf = DiffractionBrdf.create(BrdfSettings.thesis(Variant.FLSS).with(b -> b.highestOrder(1)), patch, terms);
        for (Direction wi : directions()) {
            assertSane(brdf.relative(wi, wi.specular(), 550), "4096^2 specular " + wi);
            assertSane(brdf.xyz(wi, Direction.fromSphericalDeg(45, 90)).y(), "4096^2 " + wi);
        }
        // the first order of the 16-pixel (0.8 um) ripple at normal incidence: x = lambda / d
        Direction normal = new Direction(0, 0, 1);
        double order = brdf.relative(normal, Direction.fromProjected(-0.55 / 0.8, 0), 550);
        assertTrue(order > 1e-3, "first order of the ripple: " + order);
    }

    @Test
    void zeroTaylorTermsIsTheFlatMirror() {
        // N = 0 keeps only DFT_0 = delta at zero frequency: every patch looks like a mirror
        HeightField patch = NaiveDft.randomPatch(8, 8, 0.3, 0.1, 5);
        TaylorTerms terms = TaylorTermComputer.compute(patch, 0, Reporter.SILENT);
        DiffractionBrdf brdf = DiffractionBrdf.create(BrdfSettings.thesis(Variant.FLSS).with(b -> b.highestOrder(0)), patch, terms);
        Direction normal = new Direction(0, 0, 1);
        assertEquals(1.0, brdf.xyz(normal, normal).y(), 1e-12);
        checkAllVariants(patch, 0, "N = 0");
    }

    @Test
    void pqAtIntegerLookupsWhereOneMinusCosVanishes() {
        HeightField patch = NaiveDft.randomPatch(10, 10, 0.2, 0.1, 9);
        TaylorTerms terms = TaylorTermComputer.compute(patch, 20, Reporter.SILENT);
        TaylorSincSpectrum pq = new TaylorSincSpectrum(terms, 20, 1, 7, 7, WindowPlacement.FIXED);
        double lambdaUm = 0.5;
        for (int m = -4; m <= 4; m++) {
            for (double eps : new double[] {0, 1e-12, 1e-9, 1e-7, 1e-6, 1e-3}) {
                double u = (m + eps) * lambdaUm / pq.extentXUm(); // s = m + eps: 1 - cos(omega T) ~ eps^2
                double p = pq.power(u, 0.0, -1.5, lambdaUm);
                assertSane(p, "PQ at s = " + m + " + " + eps);
            }
            // the replication factor is continuous across the guard
            assertEquals(TaylorSincSpectrum.normalisedDirichlet(m + 1e-6, 7),
                    TaylorSincSpectrum.normalisedDirichlet(m + 1.0000001e-6, 7), 1e-9);
            assertEquals(1.0, Math.abs(TaylorSincSpectrum.normalisedDirichlet(m, 7)), 1e-15);
        }
    }

    private static double[] filled(int n, double value) {
        double[] a = new double[n];
        java.util.Arrays.fill(a, value);
        return a;
    }
}
