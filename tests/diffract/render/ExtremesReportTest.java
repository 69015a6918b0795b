package diffract.render;

import diffract.util.TestReport;
import diffract.jrtr.GlTestSupport;
import diffract.optics.BrdfMap;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.TaylorEvaluation;
import diffract.optics.spectra.TaylorExpansion;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.Variant;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The extremes matrix, measured against the CPU reference on the CPU and on the GPU, and written as the
 * table of {@code docs/measurements/extremes.md} ({@code bash docs/measurements/extremes.sh} reruns it and copies
 * {@code target/extremes.md} there). Every map (colour, and monochromatic at 380 and 780 nm) of every variant on
 * every engine must be finite and non-negative; FLSS on the automatic expansion must meet the reference (the other
 * variants' errors are their own, measured and reported, see docs/measurements/accuracy.md).
 *
 * <p>Cases: blazed gratings (period 2.5 um, 20 pixels of 0.125 um, 4 periods, 8 rows) with max|h| 0.01, 0.1, 0.5,
 * 1 and 2 um (x = 2 k max|h| up to 66 at 380 nm), a flat (constant) patch, a 1 x 1 patch, an odd non-square
 * 21 x 5 grating; light at theta_i = 0, 60 and 89.9 degrees (the map's pixels reach theta_r = 80 degrees; the
 * exact specular direction and theta_r = 89.9 are held by ExtremesTest and GpuFinitenessTest); N = 0 and N = 100
 * on the 0.5 um grating. 24 x 24 maps, coherence length 10 um (so the orders of these 10 um patches are a few
 * pixels wide).
 */
@Tag("gl")
@Tag(GlTestSupport.LONG_TAG)
class ExtremesReportTest {
    private static final int SIZE = 24;
    private static final double[] THETAS_DEG = {0, 60, 89.9};
    private static final Variant[] VARIANTS = {Variant.FLSS, Variant.NMM, Variant.PQ};
    /**
     * FLSS on the automatic path against the reference. Monochromatic: max |rho - rho_ref| / max rho_ref; the
     * (2R+1)^2 = 9 texel window against the reference's full window costs up to 2e-2 here (sigma_f = 0.64
     * texels: the window's weight beyond 1.5 texels is 6 %, partly inside the stored band). Colour: mean CIEDE2000
     * over the disk <= 1 (about one just-noticeable difference). Measured: see docs/measurements/extremes.md.
     */
    private static final double FLSS_MAX_RELATIVE = 0.1;
    private static final double FLSS_MAX_MEAN_DE = 1.0;

    private record Case(String name, HeightField patch, int highestOrder) {
    }

    private static List<Case> cases() {
        List<Case> out = new ArrayList<>();
        for (double maxH : new double[] {0.01, 0.1, 0.5, 1.0, 2.0}) {
            // a sawtooth of height H has max|h| = H / 2 after the mean is removed
            out.add(new Case(String.format(Locale.ROOT, "grating max\\|h\\| %.2f um", maxH),
                    SyntheticPatches.blazed(2.5, 2 * maxH, 20, 4, 8).meanSubtracted(), 30));
        }
        out.add(new Case("flat 5x7", SyntheticPatches.flat(5, 7, 0.1).meanSubtracted(), 30));
        out.add(new Case("1x1", HeightField.of(1, 1, new double[] {0.4}, 0.1).meanSubtracted(), 30));
        out.add(new Case("odd 21x5 grating 0.13 um", SyntheticPatches.blazed(2.5, 0.26, 7, 3, 5).meanSubtracted(), 30));
        HeightField mid = SyntheticPatches.blazed(2.5, 1.0, 20, 4, 8).meanSubtracted();
        out.add(new Case("grating 0.5 um, N = 0", mid, 0));
        out.add(new Case("grating 0.5 um, N = 100", mid, 100));
        return out;
    }

    @Test
    void everyExtremeCaseIsFiniteAndMeasuredAgainstTheReference() throws IOException {
        GlTestSupport.assumeOffscreenGl();
        StringBuilder table = new StringBuilder();
        table.append("| case | theta_i | output | variant | expansion | CPU error | GPU error | GPU error, plain series |\n")
                .append("|---|---|---|---|---|---|---|---|\n");
        List<String> failures = new ArrayList<>();
        String renderer = "";
        for (Case c : cases()) {
            TaylorTerms terms = TaylorTermComputer.compute(c.patch(), c.highestOrder(), Reporter.SILENT);
            BrdfSettings base = BrdfSettings.builder(Variant.FLSS).highestOrder(c.highestOrder()).windowRadius(1).lambdaRangeNm(380, 780).lambdaStepNm(5).coherenceLengthUm(4 * 2.5).refractiveIndex(1.5).pqReplicas(3).build();
            TaylorEvaluation auto = TaylorEvaluation.choose(TaylorExpansion.AUTO, c.patch(), terms,
                    c.highestOrder(), 380, (p, centres) -> TaylorTermComputer.computeCentred(p, centres, Reporter.SILENT),
                    Reporter.SILENT);
            DiffractionBrdf reference = DiffractionBrdf.create(base.with(b -> b.variant(Variant.REFERENCE)), c.patch(), null);
            List<Maps> referenceMaps = new ArrayList<>();
            for (double theta : THETAS_DEG) {
                referenceMaps.add(Maps.of(reference, Direction.fromSphericalDeg(theta, 0)));
            }
            for (Variant variant : VARIANTS) {
                BrdfSettings settings = base.with(b -> b.variant(variant));
                DiffractionBrdf cpu = auto.brdf(settings, c.patch());
                List<Maps> gpuMaps = new ArrayList<>();
                List<Maps> plainMaps = new ArrayList<>();
                try (GpuBrdfMap gpu = new GpuBrdfMap(auto, settings, Reporter.SILENT)) {
                    renderer = gpu.info().renderer() + ", OpenGL " + gpu.info().version();
                    for (double theta : THETAS_DEG) {
                        gpuMaps.add(Maps.of(gpu, Direction.fromSphericalDeg(theta, 0)));
                    }
                }
                if (auto.isPhaseCentred()) {
                    try (GpuBrdfMap gpu = new GpuBrdfMap(terms, settings)) {
                        for (double theta : THETAS_DEG) {
                            plainMaps.add(Maps.of(gpu, Direction.fromSphericalDeg(theta, 0)));
                        }
                    }
                }
                for (int t = 0; t < THETAS_DEG.length; t++) {
                    Direction wi = Direction.fromSphericalDeg(THETAS_DEG[t], 0);
                    Maps ref = referenceMaps.get(t);
                    Maps cpuMaps = Maps.of(cpu, wi);
                    Maps gpuMap = gpuMaps.get(t);
                    Maps plain = plainMaps.isEmpty() ? null : plainMaps.get(t);
                    String where = c.name() + " theta_i " + THETAS_DEG[t] + " " + variant.label();
                    for (String problem : new String[] {cpuMaps.problem(), gpuMap.problem()}) {
                        if (problem != null) {
                            failures.add(where + ": " + problem);
                        }
                    }
                    for (int output = 0; output < 3; output++) {
                        String cpuError = ref.error(cpuMaps, output, wi);
                        String gpuError = ref.error(gpuMap, output, wi);
                        table.append(String.format(Locale.ROOT, "| %s | %s | %s | %s | %s | %s | %s | %s |%n",
                                c.name(), THETAS_DEG[t], Maps.OUTPUTS[output], variant.label(), auto.describe(),
                                cpuError, gpuError, plain == null ? "-" : ref.error(plain, output, wi)));
                        if (variant == Variant.FLSS) {
                            for (Maps m : new Maps[] {cpuMaps, gpuMap}) {
                                double e = ref.errorValue(m, output, wi);
                                double limit = output == 0 ? FLSS_MAX_MEAN_DE : FLSS_MAX_RELATIVE;
                                if (!(e <= limit)) {
                                    failures.add(where + " " + Maps.OUTPUTS[output] + ": error " + e + " > " + limit);
                                }
                            }
                        }
                    }
                }
            }
        }
        Path out = Path.of("target", "extremes.md");
        Files.createDirectories(out.getParent());
        Files.writeString(out, table.toString());
        Files.writeString(Path.of("target", "extremes-renderer.txt"), renderer);
        TestReport.line(ExtremesReportTest.class, table);
        assertTrue(failures.isEmpty(), String.join("\n", failures));
    }

    /**
     * Where the plain float32 series starts to fail, and whether the automatic switch catches it: gratings from
     * 0.1 to 0.5 um, monochromatic GPU maps at 380 nm and normal incidence (|w| up to 2, x up to 2 k max|h|) with
     * N = 30 around 0 and with the phase-centred expansion, against the reference; written to
     * {@code target/extremes-threshold.md}. The switch must pick the centred path wherever the plain one errs by
     * more than 1e-2 of the peak, and the centred path must stay below 1e-3 everywhere.
     */
    @Test
    void thePlainSeriesFailsWhereTheSwitchSaysItDoes() throws IOException {
        GlTestSupport.assumeOffscreenGl();
        StringBuilder table = new StringBuilder("| max\\|h\\| um | x at 380 nm | estimated plain error in P | automatic"
                + " choice | GPU plain N = 30 | GPU centred |\n|---|---|---|---|---|---|\n");
        List<String> failures = new ArrayList<>();
        Direction wi = Direction.fromSphericalDeg(0, 0);
        for (double maxH : new double[] {0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.5}) {
            HeightField patch = SyntheticPatches.blazed(2.5, 2 * maxH, 20, 4, 8).meanSubtracted();
            TaylorTerms terms = TaylorTermComputer.compute(patch, 30, Reporter.SILENT);
            // a 7 x 7 window: at sigma_f = 0.64 texels it misses 3e-7 of the weight, so FLSS equals the exact model
            // up to the expansion's error
            BrdfSettings settings = BrdfSettings.builder(Variant.FLSS).highestOrder(30).windowRadius(3).lambdaRangeNm(380, 780).lambdaStepNm(5).coherenceLengthUm(4 * 2.5).refractiveIndex(1.5).pqReplicas(0).build();
            TaylorEvaluation centred = TaylorEvaluation.choose(TaylorExpansion.CENTRED, patch, terms, 30, 380,
                    (p, c) -> TaylorTermComputer.computeCentred(p, c, Reporter.SILENT), Reporter.SILENT);
            double a = 2 * 2 * Math.PI / 0.38;
            double estimate = diffract.optics.spectra.Float32Cancellation.plainSeriesError(terms, 30, a);
            boolean switches = !diffract.optics.spectra.Float32Cancellation.plainSeriesSuffices(terms, 30, 380);
            float[] ref = BrdfMap.monochromatic(DiffractionBrdf.create(settings.with(b -> b.variant(Variant.REFERENCE)), patch,
                    null), wi, 380, SIZE, Reporter.SILENT);
            double plainError;
            double centredError;
            try (GpuBrdfMap gpu = new GpuBrdfMap(terms, settings)) {
                plainError = relative(gpu.monochromatic(wi, 380, SIZE), ref);
            }
            try (GpuBrdfMap gpu = new GpuBrdfMap(centred, settings, Reporter.SILENT)) {
                centredError = relative(gpu.monochromatic(wi, 380, SIZE), ref);
            }
            table.append(String.format(Locale.ROOT, "| %.2f | %.1f | %.2g | %s | %.2g | %.2g |%n", maxH,
                    a * patch.maxAbsHeightUm(), estimate, switches ? "centred" : "plain", plainError, centredError));
            if (plainError > 1e-2 && !switches) {
                failures.add("max|h| " + maxH + ": plain errs by " + plainError + " but the switch keeps it");
            }
            if (!(centredError < 1e-3)) {
                failures.add("max|h| " + maxH + ": centred errs by " + centredError);
            }
        }
        Files.createDirectories(Path.of("target"));
        Files.writeString(Path.of("target", "extremes-threshold.md"), table.toString());
        TestReport.line(ExtremesReportTest.class, table);
        assertTrue(failures.isEmpty(), String.join("\n", failures) + "\n" + table);
    }

    /**
     * The 4096 x 4096 patch on the CPU and the GPU against the reference. Its reference (16 transforms of 4096^2
     * complex doubles per centre) does not fit, but a patch whose heights vary along x only has P(m_x, m_y) =
     * DFT_x(exp(i a h))(m_x) delta(m_y): in the plane of incidence (v = 0, the middle row of an odd map, light at
     * phi_i = 0) it equals the P of its single row, whose reference is cheap. A blazed grating 0.02 um high
     * (period 0.8 um, 16 pixels of 0.05 um, 256 periods, 4096 rows: 204.8 um square), N = 4 (x = 0.33 at 380 nm,
     * remainder 0.33^5 / 5! = 3e-5): 5 layers of 128 MiB; 33 x 33 monochromatic maps. Written to {@code target/extremes-4096.md}.
     */
    @Test
    void a4096By4096PatchMeetsTheReferenceInThePlaneOfIncidence() throws IOException {
        GlTestSupport.assumeOffscreenGl();
        int size = 33;
        int middleRow = size / 2; // y = 0 exactly
        HeightField big = SyntheticPatches.blazed(0.8, 0.02, 16, 256, 4096).meanSubtracted();
        HeightField row = SyntheticPatches.blazed(0.8, 0.02, 16, 256, 1).meanSubtracted();
        // sigma_f = 204.8 um / (2 pi 16.25 um) = 2 texels: a 25 x 25 window leaves out weights below 3e-9, so
        // FLSS's window equals the reference's
        BrdfSettings settings = BrdfSettings.thesis(Variant.FLSS).with(b -> b.highestOrder(4)).with(b -> b.windowRadius(12));
        TaylorTerms terms = TaylorTermComputer.compute(big, 4, Reporter.SILENT);
        DiffractionBrdf cpu = DiffractionBrdf.create(settings, big, terms);
        DiffractionBrdf reference = DiffractionBrdf.create(settings.with(b -> b.variant(Variant.REFERENCE)), row, null);
        StringBuilder table = new StringBuilder("| theta_i | lambda | CPU flss | GPU flss |\n|---|---|---|---|\n");
        List<String> failures = new ArrayList<>();
        try (GpuBrdfMap gpu = new GpuBrdfMap(terms, settings)) {
            for (double theta : THETAS_DEG) {
                Direction wi = Direction.fromSphericalDeg(theta, 0);
                for (double lambda : new double[] {380, 780}) {
                    float[] ref = middle(BrdfMap.monochromatic(reference, wi, lambda, size, Reporter.SILENT), size,
                            middleRow);
                    float[] cpuRow = middle(BrdfMap.monochromatic(cpu, wi, lambda, size, Reporter.SILENT), size,
                            middleRow);
                    float[] gpuMap = gpu.monochromatic(wi, lambda, size);
                    for (float v : gpuMap) {
                        if (!Float.isFinite(v) || v < 0) {
                            failures.add("4096^2 GPU at " + theta + " deg, " + lambda + " nm: value " + v);
                            break;
                        }
                    }
                    double cpuError = relative(cpuRow, ref);
                    double gpuError = relative(middle(gpuMap, size, middleRow), ref);
                    table.append(String.format(Locale.ROOT, "| %s | %.0f nm | rel %.2g | rel %.2g |%n", theta, lambda,
                            cpuError, gpuError));
                    // float32 terms and the float32 lookup of a 4096-texel band: 1e-3 of the peak
                    if (!(cpuError < 1e-3 && gpuError < 1e-3)) {
                        failures.add("4096^2 at " + theta + " deg, " + lambda + " nm: CPU " + cpuError + ", GPU "
                                + gpuError);
                    }
                }
            }
        }
        Files.createDirectories(Path.of("target"));
        Files.writeString(Path.of("target", "extremes-4096.md"), table.toString());
        TestReport.line(ExtremesReportTest.class, table);
        assertTrue(failures.isEmpty(), String.join("\n", failures) + "\n" + table);
    }

    private static float[] middle(float[] map, int size, int row) {
        float[] out = new float[size];
        System.arraycopy(map, row * size, out, 0, size);
        return out;
    }

    /** max |a - ref| / max ref; infinite when a holds NaN or Inf. */
    private static double relative(float[] a, float[] ref) {
        double peak = 0;
        double worst = 0;
        for (int i = 0; i < a.length; i++) {
            peak = Math.max(peak, ref[i]);
            worst = Math.max(worst, Math.abs(a[i] - ref[i]));
        }
        return Double.isFinite(worst) ? worst / peak : Double.POSITIVE_INFINITY;
    }

    /** One light direction's colour map and monochromatic maps at 380 and 780 nm. */
    private record Maps(float[] xyz, float[] mono380, float[] mono780) {
        static final String[] OUTPUTS = {"colour", "380 nm", "780 nm"};

        static Maps of(DiffractionBrdf brdf, Direction wi) {
            return new Maps(BrdfMap.xyz(brdf, wi, SIZE, Reporter.SILENT),
                    BrdfMap.monochromatic(brdf, wi, 380, SIZE, Reporter.SILENT),
                    BrdfMap.monochromatic(brdf, wi, 780, SIZE, Reporter.SILENT));
        }

        static Maps of(GpuBrdfMap gpu, Direction wi) {
            return new Maps(gpu.xyz(wi, SIZE), gpu.monochromatic(wi, 380, SIZE), gpu.monochromatic(wi, 780, SIZE));
        }

        float[] mono(int output) {
            return output == 1 ? mono380 : mono780;
        }

        /** The first NaN, Inf or negative value (X, Z may be negative? no: CMFs and |P|^2 are >= 0), or null. */
        String problem() {
            for (float[] a : new float[][] {xyz, mono380, mono780}) {
                for (float v : a) {
                    if (!Float.isFinite(v) || v < 0) {
                        return "value " + v;
                    }
                }
            }
            return null;
        }

        /** Colour: mean CIEDE2000 over the disk (reference's auto exposure); mono: max |d| / reference peak. */
        double errorValue(Maps other, int output, Direction wi) {
            if (output == 0) {
                return RenderTestSupport.difference(xyz, other.xyz, SIZE, wi).disk().mean();
            }
            float[] ref = mono(output);
            float[] actual = other.mono(output);
            double peak = 0;
            double worst = 0;
            for (int i = 0; i < ref.length; i++) {
                peak = Math.max(peak, ref[i]);
                worst = Math.max(worst, Math.abs(actual[i] - ref[i]));
            }
            if (!Double.isFinite(worst)) {
                return Double.POSITIVE_INFINITY;
            }
            return peak > 0 ? worst / peak : worst;
        }

        String error(Maps other, int output, Direction wi) {
            double e = errorValue(other, output, wi);
            if (output == 0) {
                BrdfMapDifference d = RenderTestSupport.difference(xyz, other.xyz, SIZE, wi);
                return String.format(Locale.ROOT, "dE %.3f (lit %s)", e,
                        d.lit() == null ? "-" : String.format(Locale.ROOT, "%.2f", d.lit().mean()));
            }
            return String.format(Locale.ROOT, "rel %.2g", e);
        }
    }
}
