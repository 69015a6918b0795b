package diffract.render;

import diffract.colour.MirrorNormalisation;
import diffract.jrtr.GlTestSupport;
import diffract.optics.BrdfMap;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.spectra.PhaseCentredTerms;
import diffract.optics.spectra.PhaseCentres;
import diffract.optics.settings.PixelFilter;
import diffract.optics.TaylorEvaluation;
import diffract.optics.spectra.TaylorExpansion;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.settings.TermFormat;
import diffract.optics.Variant;
import diffract.optics.windows.WindowPlacement;
import diffract.precompute.TaylorTermComputer;
import diffract.precompute.ThesisExtrema;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import java.util.ArrayList;
import java.util.List;
import java.util.function.UnaryOperator;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The GPU map equals the CPU map of the same variant, expansion, stored terms and early stop, as people see them:
 * both XYZ maps through the exposure {@link diffract.optics.maps.AutoExposure} picks from the CPU map (the brightest
 * diffracted pixel at Y = 1, so the orders fill the display range), compared in CIEDE2000 (D65 white) over the lit
 * pixels (exposed Y above 1 % of white in either map), where a wrong colour shows; most of a map is black in both.
 *
 * <p>The CPU evaluates the terms as the GPU stores them (half precision rounded, or the thesis' 8-bit bytes
 * de-normalised), so what is left is the shader's float32 arithmetic against the CPU's double: the sums' largest
 * partial terms are about e^{k |w| h_max} (k |w| h_max up to 6.6 on the Elaphe-like patch), so cancellation costs at
 * most 3 of float32's 7 digits, a relative error near 1e-4 in |P|^2, below 0.1 CIEDE2000 at any lightness. The
 * limits, mean {@value #MAX_LIT_MEAN} and 99th percentile {@value #MAX_LIT_P99} over the lit pixels, are several
 * times what float32 costs and far below a wrong colour: {@link #aWrongColourFailsTheLimits} shows a refractive
 * index of 1.6 instead of 1.5 exceeding them. The measured numbers are in {@code target/test-reports/}.
 */
@Tag("gl")
class GpuCpuAgreementTest {
    static final int SIZE = 48;
    static final double MAX_LIT_MEAN = 0.05;
    static final double MAX_LIT_P99 = 0.5;
    /** Fewer lit pixels than this would make the statistics meaningless. */
    static final int MIN_LIT_PIXELS = 30;
    static final double[] LIGHTS_DEG = {30, 60};

    static Stream<Arguments> cases() {
        List<Arguments> cases = new ArrayList<>();
        for (Variant variant : List.of(Variant.FLSS, Variant.NMM, Variant.PQ)) {
            for (TaylorExpansion expansion : List.of(TaylorExpansion.PLAIN, TaylorExpansion.CENTRED)) {
                for (TermFormat format : TermFormat.values()) {
                    for (boolean earlyStop : new boolean[] {false, true}) {
                        if (expansion == TaylorExpansion.CENTRED && format == TermFormat.RG8) {
                            continue; // refused: see centredTermsAreNotStoredAsBytes
                        }
                        cases.add(Arguments.of(variant, expansion, format, earlyStop));
                    }
                }
            }
        }
        return cases.stream();
    }

    @ParameterizedTest(name = "{0} {1} {2} early stop {3}")
    @MethodSource("cases")
    void gpuEqualsCpuOnTheLitPixels(Variant variant, TaylorExpansion expansion, TermFormat format, boolean earlyStop) {
        GlTestSupport.assumeOffscreenGl();
        HeightField patch = RenderTestSupport.ELAPHE_LIKE;
        BrdfSettings settings = settings(variant, format, earlyStop);
        String label = variant + " " + expansion + " " + format + (earlyStop ? " early stop" : "");
        assertAgreement(patch, settings, expansion, label, UnaryOperator.identity(), true);
    }

    /** The three variants on the blazed grating too (period along x), float32 terms, the thesis' series. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void gpuEqualsCpuOnTheBlazedGrating(Variant variant) {
        GlTestSupport.assumeOffscreenGl();
        assertAgreement(RenderTestSupport.BLAZED, settings(variant, TermFormat.RG32F, false), TaylorExpansion.PLAIN,
                variant + " blazed", UnaryOperator.identity(), true);
    }

    static Stream<Variant> variants() {
        return Stream.of(Variant.FLSS, Variant.NMM, Variant.PQ);
    }

    /**
     * The lobes method at the thesis' 65 um coherence (its home; at 10 um the shader would need texel pairs), pixel
     * boxes, a point light and a 2-degree light in the plane of the period, and the 2-degree light tilted 30 degrees
     * off it (its Gauss-Hermite shifts), on 64 x 64 maps (orders narrower than a pixel light fewer pixels): both
     * patches with float32 terms, the Elaphe-like patch with every stored format (which the lobes method does not
     * read) and the phase-centred expansion; once with the mirror's energy normalisation.
     */
    static Stream<Arguments> lobesCases() {
        List<Arguments> cases = new ArrayList<>();
        for (double[] light : new double[][] {{0, 0}, {2, 0}, {2, 30}}) {
            cases.add(Arguments.of("blazed", TaylorExpansion.PLAIN, TermFormat.RG32F, light[0], light[1],
                    MirrorNormalisation.PEAK));
            cases.add(Arguments.of("elaphe-like", TaylorExpansion.PLAIN, TermFormat.RG32F, light[0], light[1],
                    MirrorNormalisation.PEAK));
        }
        cases.add(Arguments.of("elaphe-like", TaylorExpansion.PLAIN, TermFormat.RG16F, 2.0, 0.0,
                MirrorNormalisation.PEAK));
        cases.add(Arguments.of("elaphe-like", TaylorExpansion.PLAIN, TermFormat.RG8, 2.0, 0.0,
                MirrorNormalisation.PEAK));
        cases.add(Arguments.of("elaphe-like", TaylorExpansion.CENTRED, TermFormat.RG32F, 2.0, 0.0,
                MirrorNormalisation.PEAK));
        cases.add(Arguments.of("elaphe-like", TaylorExpansion.CENTRED, TermFormat.RG16F, 0.0, 0.0,
                MirrorNormalisation.PEAK));
        cases.add(Arguments.of("elaphe-like", TaylorExpansion.PLAIN, TermFormat.RG32F, 2.0, 0.0,
                MirrorNormalisation.ENERGY));
        return cases.stream();
    }

    @ParameterizedTest(name = "lobes {0} {1} {2} light {3} deg at phi + {4}, {5}")
    @MethodSource("lobesCases")
    void lobesGpuEqualsCpuOnTheLitPixels(String patchName, TaylorExpansion expansion, TermFormat format,
                                         double lightDeg, double lightPhiDeg, MirrorNormalisation normalisation) {
        GlTestSupport.assumeOffscreenGl();
        HeightField patch = patchName.equals("blazed") ? RenderTestSupport.BLAZED : RenderTestSupport.ELAPHE_LIKE;
        BrdfSettings base = BrdfSettings.thesis(Variant.LOBES);
        BrdfSettings settings = base.with(b -> b.termFormat(format).pixelFilter(PixelFilter.BOX).lightSizeDeg(lightDeg)
                .spectral(base.spectral().withNormalisation(normalisation)));
        int size = 64;
        TaylorEvaluation gpuPath;
        DiffractionBrdf cpu;
        if (expansion == TaylorExpansion.CENTRED) {
            PhaseCentredTerms centred = centredTerms(patch);
            gpuPath = TaylorEvaluation.phaseCentred(centred);
            cpu = DiffractionBrdf.createPhaseCentred(settings, centred);
        } else {
            TaylorTerms terms = RenderTestSupport.terms(patch);
            gpuPath = TaylorEvaluation.plain(terms);
            cpu = DiffractionBrdf.create(settings, patch, terms);
        }
        // the lobes shader reads its lobe weights from a float32 table made from the terms as computed, never the
        // stored term texture: the CPU mirror has the same terms whatever the format
        try (GpuBrdfMap gpu = new GpuBrdfMap(gpuPath, settings, Reporter.SILENT)) {
            for (double thetaI : LIGHTS_DEG) {
                Direction light = RenderTestSupport.light(patch, thetaI);
                Direction wi = Direction.fromSphericalDeg(thetaI, Math.toDegrees(Math.atan2(light.y(), light.x()))
                        + lightPhiDeg);
                BrdfMapDifference c = RenderTestSupport.difference(BrdfMap.xyz(cpu, wi, size, Reporter.SILENT),
                        gpu.xyz(wi, size), size, wi);
                String where = "lobes " + expansion + " " + format + " " + patchName + " light " + lightDeg
                        + " deg at phi + " + lightPhiDeg + ", " + normalisation + ", theta_i " + thetaI + ": "
                        + c.summary();
                TestReport.line(GpuCpuAgreementTest.class, where);
                assertTrue(c.litPixels() >= 20, where + ": too few lit pixels for a meaningful comparison");
                assertTrue(c.lit().mean() <= MAX_LIT_MEAN && c.lit().p99() <= MAX_LIT_P99, where);
            }
        }
    }

    /**
     * A scan wider than the window (48 um at the thesis' 65 um coherence, sigma_f = 0.47 texels, where the fixed
     * window's nearest texel pairs weigh 0.3): each variant with the window averaged over its position (texels add as
     * powers; the lobes method sums them under a 2-degree light over pixel boxes, no refusal), and FLSS with the fixed
     * window (amplitudes add), whose map differs from the averaged one by more than the limits (the negative control:
     * the define reaches the shader).
     */
    static Stream<Arguments> wideScanCases() {
        return Stream.of(Arguments.of(Variant.FLSS, WindowPlacement.AVERAGED), Arguments.of(Variant.FLSS,
                WindowPlacement.FIXED), Arguments.of(Variant.NMM, WindowPlacement.AVERAGED), Arguments.of(Variant.PQ,
                WindowPlacement.AVERAGED), Arguments.of(Variant.LOBES, WindowPlacement.AVERAGED));
    }

    @ParameterizedTest(name = "{0} {1} window")
    @MethodSource("wideScanCases")
    void gpuEqualsCpuOnAScanWiderThanTheWindow(Variant variant, WindowPlacement placement) {
        GlTestSupport.assumeOffscreenGl();
        HeightField patch = RenderTestSupport.WIDE;
        BrdfSettings settings = BrdfSettings.thesis(variant).with(b -> b.highestOrder(16).windowPlacement(placement)
                .automaticWindowRadius(variant != Variant.LOBES).pqReplicas(3));
        if (variant == Variant.LOBES) {
            settings = settings.with(b -> b.pixelFilter(PixelFilter.BOX).lightSizeDeg(2));
        }
        assertAgreement(patch, settings, TaylorExpansion.PLAIN, variant + " " + placement, UnaryOperator.identity(),
                true);
        if (placement == WindowPlacement.FIXED) {
            assertAgreement(patch, settings, TaylorExpansion.PLAIN, variant + " fixed against averaged",
                    s -> s.with(b -> b.windowPlacement(WindowPlacement.AVERAGED)), false);
        }
    }

    /**
     * The mirror's energy normalisation reaches each variant's spectral weights on the GPU (FLSS and PQ: the uniform
     * node table; NMM: its 1 nm table, whose normaliser leaves the factor out): GPU = CPU under it, and the GPU's
     * energy-normalised map against the CPU's peak-normalised one fails the limits (the factor (555 / lambda)^2
     * moves the colours by more than float32 does).
     */
    @ParameterizedTest(name = "{0} energy")
    @MethodSource("variants")
    void gpuEqualsCpuUnderTheEnergyNormalisation(Variant variant) {
        GlTestSupport.assumeOffscreenGl();
        BrdfSettings peak = settings(variant, TermFormat.RG32F, false);
        BrdfSettings energy = peak.with(b -> b.spectral(peak.spectral().withNormalisation(MirrorNormalisation.ENERGY)));
        assertAgreement(RenderTestSupport.ELAPHE_LIKE, energy, TaylorExpansion.PLAIN, variant + " energy",
                UnaryOperator.identity(), true);
        assertAgreement(RenderTestSupport.ELAPHE_LIKE, energy, TaylorExpansion.PLAIN, variant + " energy against peak",
                s -> peak, false);
    }

    /**
     * A CPU map of a slightly different surface, refractive index 1.6 instead of 1.5 (a uniform the shader would
     * read wrongly), fails the limits: they catch a wrong colour.
     */
    @Test
    void aWrongColourFailsTheLimits() {
        GlTestSupport.assumeOffscreenGl();
        BrdfSettings settings = settings(Variant.FLSS, TermFormat.RG32F, false);
        assertAgreement(RenderTestSupport.ELAPHE_LIKE, settings, TaylorExpansion.PLAIN, "FLSS against n = 1.6",
                s -> s.with(b -> b.refractiveIndex(1.6)), false);
    }

    @Test
    void centredTermsAreNotStoredAsBytes() {
        GlTestSupport.assumeOffscreenGl();
        HeightField patch = RenderTestSupport.ELAPHE_LIKE;
        PhaseCentredTerms centred = centredTerms(patch);
        BrdfSettings bytes = settings(Variant.FLSS, TermFormat.RG8, false);
        assertThrows(diffract.optics.settings.InvalidSettingException.class,
                () -> new GpuBrdfMap(centred, bytes).close());
    }

    /**
     * N = 16, the thesis' window, 5 nm over 380-780 nm, coherence length 10 um ({@link RenderTestSupport#settings});
     * with the early stop, each lookup's loop stops at a Lagrange bound of 1e-4 and the window follows sigma_f.
     */
    private static BrdfSettings settings(Variant variant, TermFormat format, boolean earlyStop) {
        return RenderTestSupport.settings(variant).with(b -> b.highestOrder(16).termFormat(format)
                .taylorTolerance(earlyStop ? 1e-4 : 0).automaticWindowRadius(earlyStop));
    }

    /**
     * The GPU map against the CPU map of {@code cpuSettings.apply(settings)} at each light of {@link #LIGHTS_DEG}:
     * within the limits ({@code expectAgreement}), or beyond them (a negative control).
     */
    private static void assertAgreement(HeightField patch, BrdfSettings settings, TaylorExpansion expansion,
                                        String label, UnaryOperator<BrdfSettings> cpuSettings, boolean expectAgreement) {
        TermFormat format = settings.gpu().termFormat();
        TaylorEvaluation gpuPath;
        DiffractionBrdf cpu;
        if (expansion == TaylorExpansion.CENTRED) {
            PhaseCentredTerms centred = centredTerms(patch);
            gpuPath = TaylorEvaluation.phaseCentred(centred);
            cpu = DiffractionBrdf.createPhaseCentred(cpuSettings.apply(settings), stored(centred, format));
        } else {
            TaylorTerms terms = RenderTestSupport.terms(patch);
            gpuPath = TaylorEvaluation.plain(terms);
            cpu = DiffractionBrdf.create(cpuSettings.apply(settings), patch,
                    stored(terms, settings.taylor().highestOrder(), format));
        }
        boolean withinLimits = true;
        try (GpuBrdfMap gpu = new GpuBrdfMap(gpuPath, settings, Reporter.SILENT)) {
            for (double thetaI : LIGHTS_DEG) {
                Direction wi = RenderTestSupport.light(patch, thetaI);
                BrdfMapDifference c = RenderTestSupport.difference(BrdfMap.xyz(cpu, wi, SIZE, Reporter.SILENT),
                        gpu.xyz(wi, SIZE), SIZE, wi);
                String where = label + " " + RenderTestSupport.name(patch) + " theta_i " + thetaI + ": " + c.summary();
                TestReport.line(GpuCpuAgreementTest.class, where);
                assertTrue(c.litPixels() >= MIN_LIT_PIXELS, where + ": too few lit pixels for a meaningful comparison");
                boolean within = c.lit().mean() <= MAX_LIT_MEAN && c.lit().p99() <= MAX_LIT_P99;
                if (expectAgreement) {
                    assertTrue(within, where);
                }
                withinLimits &= within;
            }
        }
        if (!expectAgreement) {
            assertTrue(!withinLimits, label + ": a wrong colour passed the limits");
        }
    }

    private static PhaseCentredTerms centredTerms(HeightField patch) {
        return TaylorTermComputer.computeCentred(patch, PhaseCentres.forPatch(patch.maxAbsHeightUm(), 380),
                Reporter.SILENT);
    }

    /** Terms 0..n as the GPU stores them in {@code format}. */
    static TaylorTerms stored(TaylorTerms terms, int highestOrder, TermFormat format) {
        float[][] data = new float[highestOrder + 1][];
        for (int n = 0; n <= highestOrder; n++) {
            float[] t = terms.termData(n);
            ThesisExtrema.Term map = NormalisedTerms.mapping(terms, n);
            data[n] = new float[t.length];
            for (int i = 0; i < t.length; i++) {
                data[n][i] = switch (format) {
                    case RG32F -> t[i];
                    case RG16F -> HalfFloat.rounded(t[i]);
                    case RG8 -> NormalisedTerms.decoded(t[i], i % 2 == 0 ? map.re() : map.im());
                };
            }
        }
        return new TaylorTerms(terms.rows(), terms.cols(), terms.pixelSizeXUm(), terms.pixelSizeYUm(),
                terms.maxAbsHeightUm(), data);
    }

    private static PhaseCentredTerms stored(PhaseCentredTerms centred, TermFormat format) {
        TaylorTerms[] perCentre = new TaylorTerms[centred.centres().centreCount()];
        for (int j = 0; j < perCentre.length; j++) {
            TaylorTerms t = centred.aroundCentre(j);
            perCentre[j] = stored(t, t.highestOrder(), format);
        }
        return new PhaseCentredTerms(centred.centres(), perCentre);
    }
}
