package diffract.bench;

import diffract.optics.BrdfSettings;
import diffract.optics.HeightField;
import diffract.precompute.Precomputation;
import diffract.util.Reporter;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;

/**
 * The {@code auto} variant's calibration: the {@code --quick} sweep ({@link SweepPlan#quick}) restricted to the
 * scene's own patch, with the light at the scene's azimuth, measured once and cached under the user cache
 * ({@code <cache>/calibration/<key>.csv}, key = patch content hash and every setting that changes a
 * measurement: the light's size, the pixel filter and the Fresnel model too), so a second run with the same patch and settings does not recalibrate.
 */
public final class AutoCalibration {
    /** Map size of the calibration (as {@code bench --quick}): mean errors change little with the size. */
    public static final int SIZE_PX = 64;
    /** Bump when the plan or the measurement changes, so old calibrations are not reused. */
    static final int VERSION = 2;

    private AutoCalibration() {
    }

    /**
     * The measured calibration of a patch, from the cache or measured now (needs OpenGL).
     *
     * @param base the settings that are not swept (wavelength range, coherence, refractive index, PQ replicas)
     */
    public static List<BenchResult> of(HeightField meanSubtracted, double phiIDeg, BrdfSettings base, Path cacheRoot,
                                       Reporter reporter) {
        return of(meanSubtracted, phiIDeg, base, cacheRoot, reporter, SweepPlan.quick(SIZE_PX));
    }

    /** As above with another plan (tests use a small one); the plan is part of the cache key. */
    static List<BenchResult> of(HeightField meanSubtracted, double phiIDeg, BrdfSettings base, Path cacheRoot,
                                Reporter reporter, List<SweepPlan.Point> plan) {
        BenchPatch patch = new BenchPatch("patch", meanSubtracted, phiIDeg);
        Path file = cacheRoot.resolve("calibration").resolve(key(patch, base, plan) + ".csv");
        if (Files.isRegularFile(file)) {
            try {
                List<BenchResult> cached = ResultsTable.readCsv(file, base);
                reporter.info("auto: calibration of this patch and settings reused from " + file);
                return cached;
            } catch (IOException | RuntimeException e) { // a bad number, a short row, another version's header
                reporter.warn(file + " is damaged (" + firstLine(e) + "): calibrating again");
            }
        }
        List<BenchConfig> configs = SweepPlan.configs(List.of(patch.name()), SweepPlan.sweptVariants(true), plan, base);
        reporter.info("auto: calibrating on this patch (" + configs.size() + " configurations, once; cached in "
                + file + ")");
        BenchRunner runner = new BenchRunner(new ReferenceMaps(cacheRoot.resolve("reference-maps"), reporter),
                reporter).progressOnly("auto: calibrating");
        List<BenchResult> results = runner.run(configs, Map.of(patch.name(), patch), base, r -> { });
        try {
            Files.createDirectories(file.getParent());
            ResultsTable.writeCsv(file, results, runner.glInfo());
        } catch (IOException e) {
            reporter.info("auto: cannot write the calibration to " + file + " (" + firstLine(e)
                    + "): it is used now, not kept");
        }
        return results;
    }

    private static String firstLine(Exception e) {
        String message = e.getMessage();
        return message == null ? e.getClass().getSimpleName() : message.lines().findFirst().orElse("");
    }

    /** The user cache's calibration folder root (the precompute cache). */
    public static Path defaultCacheRoot() {
        return Precomputation.cacheRoot();
    }

    static String key(BenchPatch patch, BrdfSettings base, List<SweepPlan.Point> plan) {
        String text = String.join("|", "v" + VERSION, patch.field().contentSha256(), Csv.number(patch.phiIDeg()),
                Csv.number(base.spectral().lambdaMinNm()), Csv.number(base.spectral().lambdaMaxNm()),
                base.spectral().normalisation().key(), base.window().placement().label(),
                Csv.illuminationKey(base.illumination()), Integer.toString(base.window().pqReplicas()), plan.toString());
        try {
            byte[] hash = MessageDigest.getInstance("SHA-256").digest(text.getBytes(StandardCharsets.UTF_8));
            return HexFormat.of().formatHex(hash).substring(0, 32);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }
}
