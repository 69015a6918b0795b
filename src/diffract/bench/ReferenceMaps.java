package diffract.bench;

import diffract.optics.BrdfMap;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.Direction;
import diffract.optics.Methods;
import diffract.pipeline.DiffractionPipeline;
import diffract.pipeline.NamedPatch;
import diffract.util.DiskCache;
import diffract.util.Reporter;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.util.Locale;

/**
 * The CPU reference maps (exact model at 1 nm, {@link Methods.Role#EXACT}) the bench and the {@code auto} variant
 * measure against, kept in the disk cache ({@link DiskCache}, kind {@value #KIND}) by patch content hash, light, size
 * and the settings that change the reference (wavelength range, normalisation, window placement, coherence,
 * refractive index, light size, pixel filter, Fresnel model), so no run computes one of them twice.
 */
public final class ReferenceMaps {
    /** The disk cache's kind of reference maps. */
    public static final String KIND = "reference-maps";
    /** Bump when the reference or this payload changes, so old entries go unused. */
    static final int FORMAT = 1;

    private final DiskCache cache;
    private final Reporter reporter;

    /** @param cache where maps are kept ({@link DiskCache#user}; a disabled cache computes every map) */
    public ReferenceMaps(DiskCache cache, Reporter reporter) {
        this.cache = cache;
        this.reporter = reporter;
    }

    /** A reference map and the seconds its computation took (when it was cached: the seconds it took then). */
    public record Timed(float[] xyz, double seconds) {
    }

    /** XYZ of the reference map (3 floats per pixel, rows from the top), from the cache or computed and cached. */
    public float[] xyz(BenchPatch patch, double thetaIDeg, int sizePx, BrdfSettings base) {
        return timed(patch, thetaIDeg, sizePx, base).xyz();
    }

    /** As {@link #xyz}, with the computation's seconds (kept in the cache entry). */
    public Timed timed(BenchPatch patch, double thetaIDeg, int sizePx, BrdfSettings base) {
        BrdfSettings reference = base.with(b -> b.variant(Methods.Role.EXACT.method()));
        DiskCache.Key key = key(patch, thetaIDeg, sizePx, reference);
        Timed cached = cache.load(key, in -> read(in, sizePx), reporter, "computing the reference map again");
        if (cached != null) {
            return cached;
        }
        long start = System.nanoTime();
        // the path every command takes from a height field to a picture
        DiffractionBrdf brdf = DiffractionPipeline.cached(NamedPatch.of("bench:" + patch.name(), patch.field()),
                reference.spectral().lambdaMinNm()).cpuBrdf(reference, reference.spectral().lambdaMinNm(), reporter);
        float[] xyz = BrdfMap.xyz(brdf, Direction.fromSphericalDeg(thetaIDeg, patch.phiIDeg()), sizePx, reporter);
        double seconds = (System.nanoTime() - start) * 1e-9;
        Timed computed = new Timed(xyz, seconds);
        String where = cache.store(key, out -> write(out, sizePx, computed), "the reference map", reporter)
                .map(f -> "cached in " + f).orElse("not cached");
        reporter.info(String.format(Locale.ROOT, "reference map %s, theta_i %s, %dx%d: %.1f s (%s)",
                patch.name(), Csv.number(thetaIDeg), sizePx, sizePx, seconds, where));
        return computed;
    }

    static DiskCache.Key key(BenchPatch patch, double thetaIDeg, int sizePx, BrdfSettings reference) {
        return new DiskCache.Key(KIND, String.join("; ", "reference map format " + FORMAT,
                "patch sha256 " + patch.field().contentSha256(), "theta_i " + thetaIDeg, "phi_i " + patch.phiIDeg(),
                "size " + sizePx, "lambda " + reference.spectral().lambdaMinNm() + ".."
                        + reference.spectral().lambdaMaxNm(), "normalisation " + reference.spectral().normalisation(),
                "placement " + reference.window().placement(), "illumination " + reference.illumination()));
    }

    private static void write(DataOutputStream out, int sizePx, Timed map) throws IOException {
        out.writeInt(sizePx);
        out.writeDouble(map.seconds());
        DiskCache.writeFloats(out, map.xyz());
    }

    private static Timed read(DataInputStream in, int sizePx) throws IOException {
        int size = in.readInt();
        if (size != sizePx) {
            throw new IOException("it holds a " + size + " px map, not " + sizePx + " px");
        }
        double seconds = in.readDouble();
        float[] xyz = new float[3 * sizePx * sizePx];
        DiskCache.readFloats(in, xyz);
        return new Timed(xyz, seconds);
    }
}
