package diffract.bench;

import diffract.jrtr.contexts.GLInfo;
import diffract.optics.BrdfSettings;
import diffract.optics.patches.Direction;
import diffract.optics.settings.InvalidSettingException;
import diffract.pipeline.DiffractionPipeline;
import diffract.pipeline.NamedPatch;
import diffract.render.GpuBrdfMap;
import diffract.util.Reporter;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;
import java.util.function.Predicate;

/**
 * Measures configurations on the GPU: per configuration one {@link GpuBrdfMap}, the colour maps of the lights
 * {@link #LIGHTS_DEG} (error against the cached CPU reference, {@link MapError}) and the median GPU time of
 * {@link #TIMED_FRAMES} frames at theta_i = {@link #TIMED_LIGHT_DEG} (GL timer queries; the error maps before it
 * compile the shader and upload the textures, so no warm-up frame is needed). Prints one line per configuration
 * with its index, the count and the remaining time, estimated from the shader work of the configurations left.
 */
public final class BenchRunner {
    /** theta_i of the measured maps: normal, middle and grazing incidence (in the plane of the patch's period). */
    public static final List<Double> LIGHTS_DEG = List.of(0.0, 45.0, 75.0);
    public static final double TIMED_LIGHT_DEG = 45;
    public static final int TIMED_FRAMES = 10;

    private final ReferenceMaps references;
    private final Reporter reporter;
    /** Per patch, the one path from height field to picture: its terms and the expansion the settings choose. */
    private final Map<String, DiffractionPipeline> pipelines = new HashMap<>();
    private final Map<String, List<float[]>> keptMaps = new HashMap<>();
    private Predicate<BenchConfig> keepMaps = c -> false;
    private String progressTask;
    private GLInfo glInfo;

    private final List<Double> lightsDeg;

    public BenchRunner(ReferenceMaps references, Reporter reporter) {
        this(references, reporter, LIGHTS_DEG);
    }

    /** With other lights (theta_i in degrees) than {@link #LIGHTS_DEG}, e.g. for a held-out check. */
    public BenchRunner(ReferenceMaps references, Reporter reporter, List<Double> lightsDeg) {
        this.references = references;
        this.reporter = reporter;
        this.lightsDeg = List.copyOf(lightsDeg);
    }

    /** Measures every configuration in order; {@code sink} receives each result as soon as it is measured. */
    public List<BenchResult> run(List<BenchConfig> configs, Map<String, BenchPatch> patches, BrdfSettings base,
                                 Consumer<BenchResult> sink) {
        prepare(configs, patches, base);
        if (progressTask != null) {
            reporter.progress(progressTask + " " + configs.size() + " configurations", 0);
        }
        List<BenchResult> results = new ArrayList<>();
        double totalWork = 0;
        for (BenchConfig c : configs) {
            totalWork += c.workUnits();
        }
        long start = System.nanoTime();
        double doneWork = 0;
        double frameMsSum = 0;
        for (int i = 0; i < configs.size(); i++) {
            BenchConfig c = configs.get(i);
            BenchResult r;
            try {
                r = measure(c, patches.get(c.patch()), base);
            } catch (InvalidSettingException e) {
                // a configuration the variant refuses for this patch (the lobes shader where texel pairs matter)
                reporter.info(String.format(Locale.ROOT, "[%d/%d] %-16s %-5s: not measured: %s", i + 1, configs.size(),
                        c.patch(), c.settings().variant().label(), e.getMessage()));
                doneWork += c.workUnits();
                continue;
            }
            results.add(r);
            sink.accept(r);
            doneWork += c.workUnits();
            frameMsSum += r.msPerFrame();
            double elapsedS = (System.nanoTime() - start) * 1e-9;
            if (progressTask != null) {
                // the share of the time, from the same model as the lines' ETA: the time left it implies is that ETA
                double left = eta(elapsedS, i + 1, doneWork, frameMsSum, configs.size(), totalWork);
                reporter.progress(progressTask + " " + configs.size() + " configurations",
                        i + 1 == configs.size() ? 1.0 : elapsedS / (elapsedS + left));
                continue;
            }
            reporter.info(String.format(Locale.ROOT, "[%d/%d] %-16s %-5s N=%-2d step %-2s nm R=%-4s tol %-6s %-5s %dpx: "
                            + "%8.2f ms/frame, CIEDE2000 mean %.3f p95 %.3f (%d lit px)  elapsed %s, ETA %s",
                    i + 1, configs.size(), c.patch(), c.settings().variant().label(), c.settings().taylor().highestOrder(),
                    Csv.number(c.settings().spectral().lambdaStepNm()), c.windowRadiusLabel(),
                    Csv.number(c.settings().taylor().tolerance()),
                    c.textureFormat(),
                    c.sizePx(), r.msPerFrame(), r.error().mean(), r.error().p95(), r.error().litPixels(),
                    duration(elapsedS), duration(eta(elapsedS, i + 1, doneWork, frameMsSum, configs.size(),
                            totalWork))));
        }
        return results;
    }

    /**
     * Remaining seconds: a fixed cost per configuration (context, compilation, readback) plus frame time
     * proportional to the shader work, both fitted to the configurations done so far.
     */
    double eta(double elapsedS, int done, double doneWork, double frameMsSum, int total, double totalWork) {
        int framesPerConfig = lightsDeg.size() + TIMED_FRAMES;
        double frameS = framesPerConfig * frameMsSum * 1e-3;
        double perConfigS = Math.max(0, elapsedS - frameS) / done;
        double perWorkS = doneWork > 0 ? frameS / doneWork : 0;
        return perConfigS * (total - done) + perWorkS * (totalWork - doneWork);
    }

    static String duration(double seconds) {
        long s = Math.round(seconds);
        return s >= 60 ? String.format(Locale.ROOT, "%dm%02ds", s / 60, s % 60) : s + "s";
    }

    /**
     * Report progress (with the time left) under {@code task} instead of a line per configuration: for a
     * measurement that serves another command (auto's calibration), whose rows nobody reads.
     */
    public BenchRunner progressOnly(String task) {
        this.progressTask = task;
        return this;
    }

    /** Keep the GPU maps of the configurations that match (for comparisons between variants). */
    public BenchRunner keepMapsOf(Predicate<BenchConfig> which) {
        this.keepMaps = which;
        return this;
    }

    /** The kept maps of a configuration, one per light; null when not kept. */
    public List<float[]> maps(BenchConfig c) {
        return keptMaps.get(c.key());
    }

    /** The GL renderer the last configuration ran on (null before the first). */
    public GLInfo glInfo() {
        return glInfo;
    }

    /** Terms to the highest order any configuration of a patch needs, and the reference maps, before timing. */
    private void prepare(List<BenchConfig> configs, Map<String, BenchPatch> patches, BrdfSettings base) {
        Map<String, Integer> highest = new HashMap<>();
        for (BenchConfig c : configs) {
            highest.merge(c.patch(), c.settings().taylor().highestOrder(), Math::max);
            for (double theta : lightsDeg) {
                references.xyz(patches.get(c.patch()), theta, c.sizePx(), base);
            }
        }
        for (Map.Entry<String, Integer> e : highest.entrySet()) {
            BenchPatch p = patches.get(e.getKey());
            DiffractionPipeline pipeline = DiffractionPipeline.cached(NamedPatch.of("bench:" + p.name(), p.field()),
                    base.spectral().lambdaMinNm());
            pipeline.terms(e.getValue(), reporter); // computed (or read from the cache) before anything is timed
            pipelines.put(e.getKey(), pipeline);
        }
    }

    private BenchResult measure(BenchConfig c, BenchPatch patch, BrdfSettings base) {
        ReferenceSet against = ReferenceSet.of(references, patch, lightsDeg, c.sizePx(), base);
        BrdfSettings shown = against.drawnFor(c.settings());
        List<float[]> variant;
        double ms;
        try (GpuBrdfMap map = pipelines.get(c.patch()).gpuMap(shown, shown.spectral().lambdaMinNm(), reporter)) {
            variant = against.drawnBy(map);
            ms = map.medianMsPerFrame(Direction.fromSphericalDeg(TIMED_LIGHT_DEG, patch.phiIDeg()), c.sizePx(), 0,
                    TIMED_FRAMES);
            glInfo = map.info();
        }
        if (keepMaps.test(c)) {
            keptMaps.put(c.key(), variant);
        }
        return new BenchResult(c, ms, against.error(variant));
    }
}
