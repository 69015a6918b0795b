package diffract.optics;

import diffract.colour.HatFilteredSpectrum;
import diffract.colour.Xyz;
import diffract.optics.patches.Direction;
import diffract.optics.illumination.Footprint;
import diffract.optics.illumination.GainFactor;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.settings.GainModel;
import diffract.optics.settings.LightProfile;
import diffract.optics.settings.PixelFilter;
import diffract.optics.settings.SpectralSettings;
import diffract.optics.settings.WavelengthSampling;
import diffract.optics.spectra.ExactSpectrum;
import diffract.optics.spectra.TaylorGaussianSpectrum;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.spectra.TexelCoefficients;
import diffract.optics.windows.CoherenceWindow;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The lobes method (LobeSpectrum) against FLSS at fine wavelength steps and against the filtered reference.
 */
class LobeSpectrumTest {
    /**
     * Fine enough that the rule's own error is below 1e-6: 8 nodes per sigma, 0.05 nm at most, the coefficients summed
     * at every node (no weight table), every lobe (no cutoff).
     */
    // pair threshold, nodes per sigma, widest step nm, reach, weight step nm, light nodes, cutoff, weight tolerance
    static final LobeQuadrature FINE = new LobeQuadrature(1e-13, 8, 0.05, 9, 0, LobeQuadrature.DEFAULT.lightNodes(), 0,
            0);

    /** The default quadrature without its cutoff: every lobe within reach. */
    static final LobeQuadrature RULE = new LobeQuadrature(LobeQuadrature.DEFAULT.pairThreshold(),
            LobeQuadrature.DEFAULT.nodesPerSigma(), LobeQuadrature.DEFAULT.maxStepNm(), LobeQuadrature.DEFAULT.reachSigmas(),
            LobeQuadrature.DEFAULT.weightStepNm(), LobeQuadrature.DEFAULT.lightNodes(), 0,
            LobeQuadrature.DEFAULT.weightTolerance());

    /**
     * One lobe alone (a patch whose only texel is m = (3, 1), with the exact coefficient of a real texel), for window
     * widths sigma_f = 0.05, 0.3, 1 and 3 texels along x (0.7 of that along y): its wavelength integral at a point
     * equals the trapezoid rule at 0.01 nm on the same spectral density (HatFilteredSpectrum's) to 1e-6; the default
     * quadrature to 5e-3.
     */
    @ParameterizedTest
    @ValueSource(doubles = {0.05, 0.3, 1, 3})
    void oneLobeIntegratesLikeFineUniformSteps(double sigmaX) {
        HeightField patch = NaiveDft.randomPatch(16, 20, 0.3, 0.25, 5); // L_x = 5 um, L_y = 4 um
        ExactSpectrum exact = new ExactSpectrum(patch, CoherenceWindow.thesis());
        TexelCoefficients single = new TexelCoefficients() {
            @Override
            public double extentXUm() {
                return patch.widthUm();
            }

            @Override
            public double extentYUm() {
                return patch.heightExtentUm();
            }

            @Override
            public int rows() {
                return patch.rows();
            }

            @Override
            public int cols() {
                return patch.cols();
            }

            @Override
            public double maxAbsHeightUm() {
                return patch.maxAbsHeightUm();
            }

            @Override
            public Texel texel(int mx, int my) {
                return mx == 3 && my == 1 ? exact.texel(2, -3) : null;
            }
        };
        // sigma_f = L / (2 pi sigma_s): sigma_x texels along x is sigma_s = L_x / (2 pi sigma_x); y gets 0.8 sigma_x
        CoherenceWindow window = new CoherenceWindow(patch.widthUm() / (2 * Math.PI * sigmaX));
        // the segment s(lambda) passes texel (3, 1) at 520 nm, 0.3 sigma off along y
        double[] direction = {3 * 0.52 / patch.widthUm(), (1 + 0.3 * 0.8 * sigmaX) * 0.52 / patch.heightExtentUm()};
        double w = -1.7;
        double expected = uniformSteps(single, window, direction[0], direction[1], w, 0.01);
        SpectralSettings band = new SpectralSettings(380, 780, 5);
        double fine = new LobeSpectrum(single, window, band, FINE, false).xyz(direction[0], direction[1], w,
                Footprint.POINT)[1];
        double standard = new LobeSpectrum(single, window, band, LobeQuadrature.DEFAULT, true).xyz(direction[0],
                direction[1], w, Footprint.POINT)[1];
        assertTrue(expected > 1e-6, "the lobe is lit: " + expected);
        assertEquals(expected, fine, 1e-6 * expected, "fine quadrature at sigma_f = " + sigmaX);
        assertEquals(expected, standard, 5e-3 * expected, "default quadrature at sigma_f = " + sigmaX);
    }

    /** Y of sum_m G(s - m) T_m squared, trapezoid over [380, 780] nm with HatFilteredSpectrum's density. */
    private static double uniformSteps(TexelCoefficients t, CoherenceWindow window, double u, double v, double w,
                                       double stepNm) {
        HatFilteredSpectrum density = new HatFilteredSpectrum(380, 780);
        double sigmaX = window.sigmaTexels(t.extentXUm());
        double sigmaY = window.sigmaTexels(t.extentYUm());
        double[] c = new double[2];
        double[] f = new double[3];
        int steps = (int) Math.round(400 / stepNm);
        double y = 0;
        for (int j = 0; j <= steps; j++) {
            double lambda = 380 + j * stepNm;
            double lambdaUm = lambda * 1e-3;
            t.texel(3, 1).at(2 * Math.PI / lambdaUm * w, c);
            double sx = u * t.extentXUm() / lambdaUm - 3;
            double sy = v * t.extentYUm() / lambdaUm - 1;
            double g = Math.exp(-0.5 * (sx * sx / (sigmaX * sigmaX) + sy * sy / (sigmaY * sigmaY)));
            density.weight(lambda, stepNm, f); // h f(lambda), f interpolated between whole nanometres
            y += (j == 0 || j == steps ? 0.5 : 1) * g * g * (c[0] * c[0] + c[1] * c[1]) * f[1];
        }
        return y;
    }

    /**
     * With no footprint and every pair, the lobes method is FLSS with an exact wavelength integral: against FLSS at
     * 0.01 nm over the same float32 terms (a window wide enough to hold every texel that matters), at 65 um and at
     * 10 um coherence. The two differ by their spectral densities (D65 times each CMF interpolated as a product
     * between whole nanometres here, separately there: up to 3e-4 where |P|^2 changes within a nanometre) and by the
 * default rule's error (1e-2 allowed; without the cutoff, which LobeCutoffTest bounds: these directions between the
     * orders are dimmer than the lobes it skips).
     */
    @Test
    void withoutFootprintItIsFlssIntegratedExactly() {
        HeightField patch = SyntheticPatches.elapheLike(64, 4, SyntheticPatches.ELAPHE_RIDGE_PERIOD_UM, 0.3, 2L)
                .meanSubtracted();
        TaylorTerms terms = TaylorTermComputer.compute(patch, 30, Reporter.SILENT);
        for (double coherenceUm : new double[] {65, 10}) {
            CoherenceWindow window = new CoherenceWindow(coherenceUm / 4);
            int radius = (int) Math.ceil(8 * window.sigmaTexels(patch.widthUm())) + 1;
            DiffractionBrdf flss = new DiffractionBrdf(new TaylorGaussianSpectrum(terms, 30, radius, window),
                    WavelengthSampling.uniform(380, 780, 0.01), 1.5, GainModel.STAM);
            LobeSpectrum fine = LobeSpectrum.ofTerms(terms, 30, window, new SpectralSettings(380, 780, 5), FINE);
            LobeSpectrum standard = LobeSpectrum.ofTerms(terms, 30, window, new SpectralSettings(380, 780, 5), RULE);
            Direction wi = Direction.fromSphericalDeg(30, 90);
            int lit = 0;
            for (int k = 0; k < 24; k++) {
                Direction wr = Direction.fromProjected(0.01, 0.95 - k * 0.08);
                double gain = GainFactor.gainTimesShadowing(wi, wr, 1.5);
                double u = -wi.x() - wr.x();
                double v = -wi.y() - wr.y();
                double w = -wi.z() - wr.z();
                Xyz expected = flss.xyz(wi, wr);
                double scale = Math.max(expected.x(), Math.max(expected.y(), expected.z()));
                if (scale < 1e-6) {
                    continue; // between the orders: nothing to compare
                }
                lit++;
                double[] a = fine.xyz(u, v, w, Footprint.POINT);
                double[] b = standard.xyz(u, v, w, Footprint.POINT);
                String where = coherenceUm + " um, y = " + wr.y();
                assertEquals(expected.y(), gain * a[1], 5e-4 * scale, where + " (fine)");
                assertEquals(expected.x(), gain * a[0], 5e-4 * scale, where + " (fine)");
                assertEquals(expected.z(), gain * a[2], 5e-4 * scale, where + " (fine)");
                assertEquals(expected.y(), gain * b[1], 1e-2 * scale, where + " (default)");
            }
            assertTrue(lit >= 5, lit + " lit directions at " + coherenceUm + " um");
        }
    }

    /**
     * A map pixel with a light tilted off the patch's axes (the box's off-axis part of the light on three
     * Gauss-Hermite nodes) against the filtered reference, which integrates that part adaptively.
     */
    @Test
    void aTiltedLightOverAPixelAgreesWithTheReference() {
        HeightField patch = SyntheticPatches.blazed(2.5, 0.2, 20, 4, 16).meanSubtracted();
        CoherenceWindow window = CoherenceWindow.thesis();
        TaylorTerms terms = TaylorTermComputer.compute(patch, 30, Reporter.SILENT);
        BrdfSettings settings = BrdfSettings.thesis(Variant.LOBES).with(b -> b.pixelFilter(PixelFilter.BOX)
                .lightSizeDeg(2).lightProfile(LightProfile.GAUSSIAN));
        DiffractionBrdf lobes = DiffractionBrdf.create(settings, patch, terms);
        DiffractionBrdf reference = DiffractionBrdf.create(settings.with(b -> b.variant(Variant.REFERENCE)), patch, null);
        Direction wi = Direction.fromSphericalDeg(30, 30);
        int size = 64;
        int row = (int) Math.floor((1 + wi.y()) * size / 2);
        for (int column : new int[] {(int) Math.floor((-wi.x() + 0.22 + 1) * size / 2),
            (int) Math.floor((-wi.x() - 0.22 + 1) * size / 2)}) {
            Xyz expected = reference.mapPixel(wi, column, row, size);
            Xyz actual = lobes.mapPixel(wi, column, row, size);
            assertTrue(expected.y() > 1e-4, "lit: " + expected);
            assertEquals(expected.y(), actual.y(), 0.02 * expected.y(), "pixel " + column + "," + row);
            assertEquals(expected.x(), actual.x(), 0.02 * expected.y(), "pixel " + column + "," + row);
            assertEquals(expected.z(), actual.z(), 0.02 * expected.y(), "pixel " + column + "," + row);
        }
    }
}
