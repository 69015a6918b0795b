package diffract.bench;

import diffract.optics.BrdfSettings;
import diffract.optics.patches.HeightField;
import diffract.util.DiskCache;
import diffract.util.Reporter;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Map;

/**
 * The {@code auto} variant's calibration: the {@code --quick} sweep ({@link SweepPlan#quick}) restricted to the
 * scene's own patch, with the light at the scene's azimuth, measured once and kept in the disk cache
 * ({@link DiskCache}, kind {@value #KIND}; key = patch content hash and every setting that changes a measurement:
 * the light's size, the pixel filter and the Fresnel model too, and the plan), so a second run with the same patch
 * and settings does not recalibrate.
 */
public final class AutoCalibration {
    /** Map size of the calibration (as {@code bench --quick}): mean errors change little with the size. */
    public static final int SIZE_PX = 64;
    /** The disk cache's kind of calibrations. */
    public static final String KIND = "calibration";
    /** Bump when the plan or the measurement changes, so old calibrations are not reused. */
    static final int VERSION = 2;

    private AutoCalibration() {
    }

    /**
     * The measured calibration of a patch, from the cache or measured now (needs OpenGL).
     *
     * @param base  the settings that are not swept (wavelength range, coherence, refractive index, PQ replicas)
     * @param cache where calibrations and their reference maps are kept ({@link DiskCache#user}; a disabled cache
     *              measures every time)
     */
    public static List<BenchResult> of(HeightField meanSubtracted, double phiIDeg, BrdfSettings base, DiskCache cache,
                                       Reporter reporter) {
        return of(meanSubtracted, phiIDeg, base, cache, reporter, SweepPlan.quick(SIZE_PX));
    }

    /** As above with another plan (tests use a small one); the plan is part of the cache key. */
    static List<BenchResult> of(HeightField meanSubtracted, double phiIDeg, BrdfSettings base, DiskCache cache,
                                Reporter reporter, List<SweepPlan.Point> plan) {
        BenchPatch patch = new BenchPatch("patch", meanSubtracted, phiIDeg);
        DiskCache.Key key = key(patch, base, plan);
        List<BenchResult> cached = cache.load(key, in -> ResultsTable.parseCsv("the cached calibration",
                new String(in.readAllBytes(), StandardCharsets.UTF_8).lines().toList(), base), reporter,
                "calibrating again");
        if (cached != null) {
            reporter.info("auto: calibration of this patch and settings reused from " + cache.file(key));
            return cached;
        }
        List<BenchConfig> configs = SweepPlan.configs(List.of(patch.name()), SweepPlan.sweptVariants(true), plan, base);
        reporter.info("auto: calibrating on this patch (" + configs.size() + " configurations, once"
                + (cache.enabled() ? "; kept in the disk cache " + cache.folder() : "") + ")");
        BenchRunner runner = new BenchRunner(new ReferenceMaps(cache, reporter), reporter)
                .progressOnly("auto: calibrating");
        List<BenchResult> results = runner.run(configs, Map.of(patch.name(), patch), base, r -> { });
        byte[] csv = ResultsTable.csv(results, runner.glInfo()).getBytes(StandardCharsets.UTF_8);
        cache.store(key, out -> out.write(csv), "the calibration", reporter);
        return results;
    }

    /** The key of a calibration: the patch's content, the light's azimuth, every unswept setting and the plan. */
    static DiskCache.Key key(BenchPatch patch, BrdfSettings base, List<SweepPlan.Point> plan) {
        return new DiskCache.Key(KIND, String.join("; ", "calibration v" + VERSION,
                "patch sha256 " + patch.field().contentSha256(), "phi_i " + patch.phiIDeg(),
                "lambda " + base.spectral().lambdaMinNm() + ".." + base.spectral().lambdaMaxNm(),
                "normalisation " + base.spectral().normalisation(), "placement " + base.window().placement(),
                "illumination " + base.illumination(), "pq replicas " + base.window().pqReplicas(), "plan " + plan));
    }
}
