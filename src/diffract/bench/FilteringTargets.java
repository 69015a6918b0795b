package diffract.bench;

import diffract.jrtr.contexts.GLInfo;
import diffract.optics.maps.AutoExposure;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.BrdfSettings;
import diffract.optics.patches.Direction;
import diffract.optics.Methods;
import diffract.optics.settings.PixelFilter;
import diffract.pipeline.DiffractionPipeline;
import diffract.pipeline.NamedPatch;
import diffract.render.GpuBrdfMap;
import diffract.util.Reporter;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

/**
 * The filtering targets at the thesis' own coherence (docs/measurements/filtering.md): per patch and light size, a BRDF map at
 * theta_i = 30 degrees (light azimuth in the plane of the patch's period) whose pixels average their squares, from
 * <ul>
 *   <li>the filtered reference ({@link Methods.Role#EXACT} with {@link PixelFilter#BOX} and the light's size, cached
 *       by {@link ReferenceMaps}): the yardstick;</li>
 *   <li>the lobes method on the GPU (the settings given, {@link Methods.Role#FILTERING});</li>
 *   <li>FLSS in the thesis' configuration (N = 30, 5 nm, 3 x 3 window, {@link Methods.Role#THESIS}), which
 *       point-samples pixel and light;</li>
 *   <li>the baked table ({@link Methods.Role#TABLE}), of the lobes method where the patch allows it.</li>
 * </ul>
 * Each error is CIEDE2000 (mean and 95th percentile) over the lit pixels at the reference's display exposure
 * ({@link BrdfMapDifference}). The lobes method and FLSS are timed on the same GL context in alternating rounds of
 * frames (GL timer queries, median per round), so that a change in the machine's load moves both; the speed-up is the
 * median of the rounds' ratios. A row meets the targets when the lobes method is within mean CIEDE2000
 * {@link #MAX_DELTA_E} of the reference and at least {@link #MIN_SPEED_UP} times faster than FLSS.
 */
public final class FilteringTargets {
    public static final double THETA_I_DEG = 30;
    public static final double MAX_DELTA_E = 1;
    public static final double MIN_SPEED_UP = 10;
    /** Alternating timing rounds of the lobes method and FLSS. */
    public static final int ROUNDS = 3;
    /** (u, v) samples of the baked table measured beside them, unless the bench is told otherwise: automatic. */
    public static final int DEFAULT_BAKED_UV_SAMPLES = 0;

    /** One patch under one light: errors against the reference and GPU times (NaN where not measured). */
    public record Row(String patch, double lightDeg, int litPixels, double lobesMean, double lobesP95,
                      double flssMean, double flssP95, double bakedMean, double bakedP95, double lobesMs,
                      double flssMs, double speedUp, double bakedMs, double referenceSeconds, double bakeSeconds,
                      String bakedGrid) {
        public boolean meetsTargets() {
            return lobesMean <= MAX_DELTA_E && speedUp >= MIN_SPEED_UP;
        }
    }

    private final ReferenceMaps references;
    private final BrdfSettings lobes;
    private final int sizePx;
    private final int rounds;
    private final int framesPerRound;
    private final int bakedSamples;
    private final int bakedWSamples;
    private final Reporter reporter;
    private GLInfo glInfo;

    /**
     * @param lobes          the lobes method's settings (coherence, Fresnel, quadrature); the light size is set per row
     * @param bakedSamples   (u, v) samples of the baked table, 0 for automatic ({@link diffract.optics.BakedGrid}: what
     *                       brdfmap and the scenes take)
     * @param bakedWSamples  w samples of the baked table, 0 for automatic
     */
    public FilteringTargets(ReferenceMaps references, BrdfSettings lobes, int sizePx, int rounds, int framesPerRound,
                            int bakedSamples, int bakedWSamples, Reporter reporter) {
        this.references = references;
        this.lobes = lobes.with(b -> b.variant(Methods.Role.FILTERING.method()).pixelFilter(PixelFilter.BOX));
        this.sizePx = sizePx;
        this.rounds = rounds;
        this.framesPerRound = framesPerRound;
        this.bakedSamples = bakedSamples;
        this.bakedWSamples = bakedWSamples;
        this.reporter = reporter;
    }

    /** The thesis' configuration, point-sampled under a point light, at the same coherence and Fresnel model. */
    BrdfSettings flss() {
        return BrdfSettings.thesis(Methods.Role.THESIS.method()).with(b -> b
                .coherenceLengthUm(lobes.illumination().coherenceLengthUm()).gain(lobes.illumination().gain())
                .lightSizeDeg(0).pixelFilter(PixelFilter.POINT));
    }

    public Row measure(BenchPatch patch, DiffractionPipeline pipeline, double lightDeg) {
        BrdfSettings lobesHere = lobes.with(b -> b.lightSizeDeg(lightDeg));
        Direction wi = Direction.fromSphericalDeg(THETA_I_DEG, patch.phiIDeg());
        ReferenceMaps.Timed timed = references.timed(patch, THETA_I_DEG, sizePx, lobesHere);
        float[] reference = timed.xyz();
        double exposure = AutoExposure.ofXyz(reference, wi, sizePx);
        // the lobes method and its table drawn for the exposure they are compared at
        BrdfSettings lobesShown = lobesHere.shownAt(exposure);
        double lambdaMin = lobesHere.spectral().lambdaMinNm();
        double bakedMean = Double.NaN;
        double bakedP95 = Double.NaN;
        double bakedMs = Double.NaN;
        double bakeSeconds = Double.NaN;
        String bakedGrid = "-";
        BrdfSettings baked = lobesShown.with(b -> b.drawnBy(Methods.Role.TABLE.method())
                .bakedSamples(bakedSamples, bakedWSamples));
        try (GpuBrdfMap map = pipeline.gpuMap(baked, lambdaMin, reporter)) {
            // the bake's own seconds: a table from the disk cache keeps those of the run that baked it
            bakeSeconds = map.bakedTable().bakeSeconds();
            var grid = map.bakedTable().grid();
            bakedGrid = grid.uvSamples() + " x " + grid.uvSamples() + " x " + grid.wSamples();
            BrdfMapDifference d = BrdfMapDifference.of(reference, map.xyz(wi, sizePx), sizePx, exposure);
            if (d.lit() != null) {
                bakedMean = d.lit().mean();
                bakedP95 = d.lit().p95();
            }
            bakedMs = map.medianMsPerFrame(wi, sizePx, 2, framesPerRound);
        } catch (RuntimeException e) {
            reporter.warn(patch.name() + ": no baked table (" + e.getMessage() + ")");
        }
        try (GpuBrdfMap lobesMap = pipeline.gpuMap(lobesShown, lambdaMin, reporter);
             GpuBrdfMap flssMap = pipeline.gpuMap(flss(), lambdaMin, reporter)) {
            glInfo = lobesMap.info();
            BrdfMapDifference l = BrdfMapDifference.of(reference, lobesMap.xyz(wi, sizePx), sizePx, exposure);
            if (lobesMap.truncatedPixels() > 0) {
                reporter.warn(patch.name() + ": " + lobesMap.truncatedPixels() + " pixels of the lobes method's map "
                        + "reach more lobes than this GL lets a fragment sum; they miss lobes (the error counts them)");
            }
            BrdfMapDifference f = BrdfMapDifference.of(reference, flssMap.xyz(wi, sizePx), sizePx, exposure);
            double[] lobesMs = new double[rounds];
            double[] flssMs = new double[rounds];
            double[] ratio = new double[rounds];
            for (int r = 0; r < rounds; r++) {
                lobesMs[r] = lobesMap.medianMsPerFrame(wi, sizePx, 2, framesPerRound);
                flssMs[r] = flssMap.medianMsPerFrame(wi, sizePx, 1, framesPerRound);
                ratio[r] = flssMs[r] / lobesMs[r];
            }
            return new Row(patch.name(), lightDeg, l.litPixels(), mean(l), p95(l), mean(f), p95(f), bakedMean, bakedP95,
                    median(lobesMs), median(flssMs), median(ratio), bakedMs, timed.seconds(), bakeSeconds, bakedGrid);
        }
    }

    /** The GL the maps were drawn with (null before the first row). */
    public GLInfo glInfo() {
        return glInfo;
    }

    private static double mean(BrdfMapDifference d) {
        return d.lit() == null ? Double.NaN : d.lit().mean();
    }

    private static double p95(BrdfMapDifference d) {
        return d.lit() == null ? Double.NaN : d.lit().p95();
    }

    static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }

    /** The patch as the pipeline names it (terms from the user cache, for the settings' shortest wavelength). */
    DiffractionPipeline pipelineOf(BenchPatch patch) {
        return DiffractionPipeline.cached(NamedPatch.of("bench:" + patch.name(), patch.field()),
                lobes.spectral().lambdaMinNm());
    }

    public static String csv(List<Row> rows, GLInfo gl) {
        StringBuilder s = new StringBuilder("patch,light_deg,lit_px,lobes_mean,lobes_p95,flss_mean,flss_p95,"
                + "baked_mean,baked_p95,baked_table,lobes_ms,flss_ms,speed_up,baked_ms,reference_s,bake_s,meets_targets,"
                + "gl_renderer\n");
        for (Row r : rows) {
            s.append(String.format(Locale.ROOT,
                    "%s,%s,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%s,%.3f,%.3f,%.2f,%.3f,%.1f,%.1f,%s,%s%n",
                    r.patch(), Csv.number(r.lightDeg()), r.litPixels(), r.lobesMean(), r.lobesP95(), r.flssMean(),
                    r.flssP95(), r.bakedMean(), r.bakedP95(), r.bakedGrid(), r.lobesMs(), r.flssMs(), r.speedUp(), r.bakedMs(),
                    r.referenceSeconds(), r.bakeSeconds(), r.meetsTargets(), gl == null ? "" : '"' + gl.renderer() + '"'));
        }
        return s.toString();
    }

    /** The table of docs/measurements/bench/filtering.md: one row per patch and light. */
    public static String markdown(List<Row> rows, int sizePx, BrdfSettings lobes) {
        StringBuilder s = new StringBuilder(String.format(Locale.ROOT, "%d x %d BRDF maps, theta_i = %.0f degrees, "
                        + "coherence length %s um; CIEDE2000 mean / p95 over lit pixels against the filtered reference\n\n",
                sizePx, sizePx, THETA_I_DEG, Csv.number(lobes.illumination().coherenceLengthUm())));
        s.append("| patch | light | lit px | lobes | FLSS (thesis) | baked | baked table (u x v x w) | lobes ms | FLSS ms "
                + "| FLSS / lobes | baked ms | bake s | reference s | <= ")
                .append(Csv.number(MAX_DELTA_E)).append(" and >= ").append(Csv.number(MIN_SPEED_UP)).append("x |\n");
        s.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
        for (Row r : rows) {
            s.append(String.format(Locale.ROOT,
                    "| %s | %s deg | %d | %s | %s | %s | %s | %.1f | %.1f | %.1f | %s | %s | %s | %s |%n",
                    r.patch(), Csv.number(r.lightDeg()), r.litPixels(), pair(r.lobesMean(), r.lobesP95()),
                    pair(r.flssMean(), r.flssP95()), pair(r.bakedMean(), r.bakedP95()), r.bakedGrid(), r.lobesMs(),
                    r.flssMs(),
                    r.speedUp(), Double.isNaN(r.bakedMs()) ? "-" : String.format(Locale.ROOT, "%.2f", r.bakedMs()),
                    seconds(r.bakeSeconds()), seconds(r.referenceSeconds()), r.meetsTargets() ? "yes" : "**no**"));
        }
        return s.toString();
    }

    private static String seconds(double s) {
        return Double.isNaN(s) ? "-" : String.format(Locale.ROOT, "%.0f", s);
    }

    private static String pair(double mean, double p95) {
        return Double.isNaN(mean) ? "-" : String.format(Locale.ROOT, "%.2f / %.2f", mean, p95);
    }

    /** Rows for every patch and light, in order. */
    public List<Row> run(List<BenchPatch> patches, List<Double> lightsDeg, java.util.function.Consumer<Row> done) {
        List<Row> rows = new ArrayList<>();
        for (BenchPatch p : patches) {
            DiffractionPipeline pipeline = pipelineOf(p);
            for (double light : lightsDeg) {
                Row r = measure(p, pipeline, light);
                rows.add(r);
                done.accept(r);
            }
        }
        return rows;
    }
}
