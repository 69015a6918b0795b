package diffract.render;

import diffract.app.AutoExposure;
import diffract.app.BrdfMapDifference;
import diffract.bench.BenchPatch;
import diffract.jrtr.FloatTextureArray;
import diffract.optics.BrdfMap;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.Direction;
import diffract.optics.HeightField;
import diffract.optics.LightSource;
import diffract.optics.LobeQuadrature;
import diffract.optics.OpticsOptions;
import diffract.optics.TaylorEvaluation;
import diffract.optics.TaylorTerms;
import diffract.optics.Variant;
import diffract.optics.io.HeightFieldReader;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * The measurements of docs/filtering.md (not a test: it asserts nothing and runs only with
 * {@code -Ddiffract.measure=filtering}). At the thesis' 65 um coherence, 64 x 64 BRDF maps at theta_i = 30 degrees
 * (light azimuth in the plane of the patch's period) of the bench patches and of the shared Elaphe patch
 * ({@code ../shared/data/patches/elaphe-100px.png}, 0.375 um, 0.0686 um pixels), with a point light and a 2-degree
 * light: CIEDE2000 (mean and 95th percentile over lit pixels, the reference's auto exposure) of the lobes method
 * (CPU and GPU) and of FLSS in the thesis' configuration (30 terms, 5 nm, 3 x 3; point-sampled, point light only)
 * against the filtered reference, the baked table of the lobes method ({@code -Ddiffract.bakedSamples}, 256 (u, v)
 * samples by default, cell- and light-averaged, mip-mapped), and the GPU's median ms per frame of each (FLSS on the
 * path TaylorEvaluation picks, the lobes method likewise): lobes and FLSS in rounds of 10 frames each, one after the
 * other, the ratio the median of the rounds' ratios. The reference maps are cached under target/filtering-cache.
 * Prints markdown rows.
 *
 * <pre>xvfb-run -a mvn -q test -Dtest=FilteringMeasurement -Ddiffract.measure=filtering</pre>
 *
 * Options: {@code -Ddiffract.patches=blazed,elaphe-like,...}, {@code -Ddiffract.lights=0,2},
 * {@code -Ddiffract.thetas=30}, {@code -Ddiffract.size=64}, {@code -Ddiffract.lobes=q,step,reach,wstep[,cutoff[,wtol]]}
 * (the quadrature: nodes per sigma, widest step nm, reach sigmas, weight step nm, cutoff, weight tolerance),
 * {@code -Ddiffract.gpu=false}, {@code -Ddiffract.cpu=false} (no CPU map), {@code -Ddiffract.bakedSamples=0} (no
 * baked table), {@code -Ddiffract.rounds=3} (timing rounds).
 */
@Tag("gl")
class FilteringMeasurement {
    static final Path CACHE = Path.of("target", "filtering-cache");
    static final Path ELAPHE = Path.of("..", "shared", "data", "patches", "elaphe-100px.png");

    @Test
    void measure() throws IOException {
        Assumptions.assumeTrue("filtering".equals(System.getProperty("diffract.measure")), "measurement only on request");
        int size = Integer.getInteger("diffract.size", 64);
        boolean gpu = Boolean.parseBoolean(System.getProperty("diffract.gpu", "true"));
        if (gpu) {
            RenderTestSupport.assumeDisplay();
        }
        LobeQuadrature quadrature = quadrature(System.getProperty("diffract.lobes"));
        System.out.println("lobes quadrature: " + quadrature);
        int bakedSamples = Integer.getInteger("diffract.bakedSamples", 256);
        boolean cpu = Boolean.parseBoolean(System.getProperty("diffract.cpu", "true"));
        System.out.println("| patch | light | theta_i | lit px | lobes CPU: mean / p95 | lobes GPU: mean / p95 | "
                + "flss (thesis): mean / p95 | baked " + bakedSamples + ": mean / p95 | lobes ms | flss ms | "
                + "flss / lobes | baked ms (bake s, MB) |");
        System.out.println("|---|---|---|---|---|---|---|---|---|---|---|---|");
        for (String name : System.getProperty("diffract.patches", "blazed,elaphe-like,xenopeltis-like,tall,elaphe-100px")
                .split(",")) {
            HeightField field;
            double phi;
            if (name.equals("elaphe-100px")) {
                if (!Files.exists(ELAPHE)) {
                    continue;
                }
                field = HeightFieldReader.load(ELAPHE, 0.375, 0.0686, Reporter.SILENT).meanSubtracted();
                phi = 90;
            } else {
                BenchPatch patch = BenchPatch.named(name);
                field = patch.field();
                phi = patch.phiIDeg();
            }
            TaylorTerms terms = TaylorTermComputer.compute(field, 30, Reporter.SILENT);
            for (String light : System.getProperty("diffract.lights", "0,2").split(",")) {
                for (String theta : System.getProperty("diffract.thetas", "30").split(",")) {
                    measure(name, field, terms, phi, Double.parseDouble(theta), Double.parseDouble(light), size,
                            quadrature, gpu, cpu, bakedSamples);
                }
            }
        }
    }

    static LobeQuadrature quadrature(String text) {
        LobeQuadrature q = LobeQuadrature.DEFAULT;
        if (text == null) {
            return q;
        }
        String[] p = text.split(",");
        q = q.withNodesPerSigma(Double.parseDouble(p[0])).withMaxStepNm(Double.parseDouble(p[1]))
                .withReachSigmas(Double.parseDouble(p[2])).withWeightStepNm(Double.parseDouble(p[3]));
        if (p.length > 4) {
            q = q.withCutoff(Double.parseDouble(p[4]));
        }
        if (p.length > 5) {
            q = q.withWeightTolerance(Double.parseDouble(p[5]));
        }
        return q;
    }

    private static void measure(String name, HeightField field, TaylorTerms terms, double phi, double thetaDeg,
                                double lightDeg, int size, LobeQuadrature quadrature, boolean gpu, boolean cpu,
                                int bakedSamples)
            throws IOException {
        Direction wi = Direction.fromSphericalDeg(thetaDeg, phi);
        OpticsOptions options = OpticsOptions.DEFAULT.withLight(new LightSource(lightDeg)).withLobes(quadrature);
        BrdfSettings thesis = BrdfSettings.thesis(Variant.FLSS);
        TaylorEvaluation evaluation = TaylorEvaluation.choose(TaylorEvaluation.Mode.AUTO, field, terms, 30, 380,
                (patch, centres) -> TaylorTermComputer.computeCentred(patch, centres, Reporter.SILENT), Reporter.SILENT);
        float[] reference = referenceMap(name, field, wi, options, size, thetaDeg, lightDeg);
        float[] luminance = new float[size * size];
        for (int p = 0; p < luminance.length; p++) {
            luminance[p] = reference[3 * p + 1];
        }
        double exposure = AutoExposure.of(luminance, size, -wi.x(), -wi.y());
        BrdfSettings lobesSettings = thesis.withVariant(Variant.LOBES);
        DiffractionBrdf lobes = evaluation.brdf(lobesSettings, field, options);
        String cpuCell = "-";
        int litPixels = -1;
        if (cpu) {
            float[] lobesCpu = BrdfMap.xyz(lobes, wi, size, Reporter.SILENT);
            BrdfMapDifference d = BrdfMapDifference.of(reference, lobesCpu, size, exposure);
            cpuCell = cell(d);
            litPixels = d.litPixels();
        }
        String gpuCell = "-";
        String flssCell = "-";
        String times = "- | - | -";
        String bakedCell = "-";
        String bakedTime = "-";
        if (gpu) {
            BrdfSettings bakedSettings = thesis.withVariant(Variant.BAKED).withBakedSamples(bakedSamples, 0);
            // the baked table holds the thesis' series around 0 only: not on the phase-centred path
            try (GpuBrdfMap map = evaluation.isPhaseCentred() || bakedSamples == 0 ? null : GpuBrdfMap.of(evaluation, bakedSettings,
                    options, FloatTextureArray.Precision.FLOAT32)) {
                if (map == null) {
                    throw new SkipBaked();
                }
                BrdfMapDifference d = BrdfMapDifference.of(reference, map.xyz(wi, size), size, exposure);
                bakedCell = cell(d);
                bakedTime = String.format(Locale.ROOT, "%.2f (%.0f s, %.1f MB)", map.medianMsPerFrame(wi, size, 2, 10),
                        map.bakedTable().bakeSeconds(), map.bakedTable().gpuBytes() / 1e6);
            } catch (SkipBaked e) {
                bakedCell = bakedSamples == 0 ? "-" : "(centred)";
            }
            OpticsOptions pointLight = options.withLight(LightSource.POINT);
            try (GpuBrdfMap lobesMap = GpuBrdfMap.of(evaluation, lobesSettings, options,
                    FloatTextureArray.Precision.FLOAT32);
                 GpuBrdfMap flssMap = GpuBrdfMap.of(evaluation, thesis, pointLight, FloatTextureArray.Precision.FLOAT32)) {
                BrdfMapDifference d = BrdfMapDifference.of(reference, lobesMap.xyz(wi, size), size, exposure);
                gpuCell = cell(d);
                litPixels = d.litPixels();
                flssCell = cell(BrdfMapDifference.of(reference, flssMap.xyz(wi, size), size, exposure));
                // rounds of lobes and FLSS frames one after the other, so that a change in the machine's load
                // between them moves both: the ratio is the median of the rounds' ratios
                int rounds = Integer.getInteger("diffract.rounds", 3);
                double[] lobesMs = new double[rounds];
                double[] flssMs = new double[rounds];
                double[] ratio = new double[rounds];
                for (int r = 0; r < rounds; r++) {
                    lobesMs[r] = lobesMap.medianMsPerFrame(wi, size, 2, 10);
                    flssMs[r] = flssMap.medianMsPerFrame(wi, size, 1, 10);
                    ratio[r] = flssMs[r] / lobesMs[r];
                }
                times = String.format(Locale.ROOT, "%.1f | %.1f | %.1f", median(lobesMs), median(flssMs), median(ratio));
            }
        }
        System.out.printf(Locale.ROOT, "| %s | %s deg | %.0f | %d | %s | %s | %s | %s | %s | %s |%n", name, fmt(lightDeg),
                thetaDeg, litPixels, cpuCell, gpuCell, flssCell, bakedCell, times, bakedTime);
    }

    private static double median(double[] values) {
        double[] sorted = values.clone();
        java.util.Arrays.sort(sorted);
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }

    private static String fmt(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
    }

    private static String cell(BrdfMapDifference d) {
        if (d.lit() == null) {
            return "- / -";
        }
        return String.format(Locale.ROOT, "%.2f / %.2f", d.lit().mean(), d.lit().p95());
    }

    /** The filtered reference's map, cached by patch, angle, light and size. */
    static float[] referenceMap(String name, HeightField field, Direction wi, OpticsOptions options, int size,
                                double thetaDeg, double lightDeg) throws IOException {
        Path file = CACHE.resolve(String.format(Locale.ROOT, "%s-%.1f-%.4f-%.4f-%.2f-%d-%s.bin", name, thetaDeg, wi.x(),
                wi.y(), lightDeg, size, field.contentSha256().substring(0, 12)));
        if (Files.exists(file)) {
            try (DataInputStream in = new DataInputStream(Files.newInputStream(file))) {
                float[] map = new float[3 * size * size];
                for (int i = 0; i < map.length; i++) {
                    map[i] = in.readFloat();
                }
                return map;
            }
        }
        BrdfSettings settings = BrdfSettings.thesis(Variant.REFERENCE);
        DiffractionBrdf reference = DiffractionBrdf.create(settings, field, null, options);
        float[] map = BrdfMap.xyz(reference, wi, size, Reporter.SILENT);
        Files.createDirectories(CACHE);
        try (DataOutputStream out = new DataOutputStream(Files.newOutputStream(file))) {
            for (float v : map) {
                out.writeFloat(v);
            }
        }
        return map;
    }

    /** The baked table is not made on the phase-centred path. */
    private static final class SkipBaked extends RuntimeException {
        SkipBaked() {
            super(null, null, false, false);
        }
    }
}
