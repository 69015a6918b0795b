package diffract.bench;

import diffract.optics.BrdfMap;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.Direction;
import diffract.optics.Variant;
import diffract.util.ImageFiles;
import diffract.util.Reporter;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * The CPU reference maps (exact model at 1 nm, {@link Variant#REFERENCE}) the bench measures against, cached as
 * PFM files of XYZ under a folder, named by patch content hash, light, size and the settings that change the
 * reference (wavelength range, coherence, refractive index, light size, pixel filter, Fresnel model), so reruns compute none of them again.
 */
public final class ReferenceMaps {
    private final Path dir;
    private final Reporter reporter;

    public ReferenceMaps(Path dir, Reporter reporter) {
        this.dir = dir;
        this.reporter = reporter;
    }

    /** A reference map and the seconds its computation took (when it was cached: the seconds it took then). */
    public record Timed(float[] xyz, double seconds) {
    }

    /** XYZ of the reference map (3 floats per pixel, rows from the top), from the cache or computed and cached. */
    public float[] xyz(BenchPatch patch, double thetaIDeg, int sizePx, BrdfSettings base) {
        return timed(patch, thetaIDeg, sizePx, base).xyz();
    }

    /** As {@link #xyz}, with the computation's seconds (kept beside the cached map; NaN for a map cached without). */
    public Timed timed(BenchPatch patch, double thetaIDeg, int sizePx, BrdfSettings base) {
        BrdfSettings reference = base.with(b -> b.variant(Variant.REFERENCE));
        Path file = dir.resolve(String.format(Locale.ROOT, "%s-t%s-p%s-s%d-l%s-%s-%s-%s-%s.pfm",
                patch.field().contentSha256().substring(0, 16), Csv.number(thetaIDeg), Csv.number(patch.phiIDeg()),
                sizePx, Csv.number(reference.spectral().lambdaMinNm()), Csv.number(reference.spectral().lambdaMaxNm()),
                reference.spectral().normalisation().key(), reference.window().placement().label(),
                Csv.illuminationKey(reference.illumination())));
        if (Files.isRegularFile(file)) {
            try {
                int[] whc = new int[3];
                float[] xyz = ImageFiles.readPfm(file, whc);
                if (whc[0] == sizePx && whc[1] == sizePx && whc[2] == 3) {
                    return new Timed(xyz, cachedSeconds(file));
                }
                reporter.warn(file + " holds a map of another size: recomputing it");
            } catch (IOException e) {
                reporter.warn(file + " is damaged (" + e.getMessage() + "): recomputing it");
            }
        }
        long start = System.nanoTime();
        DiffractionBrdf brdf = DiffractionBrdf.create(reference, patch.field(), null);
        float[] xyz = BrdfMap.xyz(brdf, Direction.fromSphericalDeg(thetaIDeg, patch.phiIDeg()), sizePx, reporter);
        double seconds = (System.nanoTime() - start) * 1e-9;
        String where;
        try {
            Files.createDirectories(dir);
            ImageFiles.writePfm(file, xyz, sizePx, sizePx, 3);
            Files.writeString(secondsFile(file), String.format(Locale.ROOT, "%.1f%n", seconds));
            where = "cached in " + file;
        } catch (IOException e) {
            where = "not cached: cannot write " + dir + " (" + e.getMessage() + ")";
        }
        reporter.info(String.format(Locale.ROOT, "reference map %s, theta_i %s, %dx%d: %.1f s (%s)",
                patch.name(), Csv.number(thetaIDeg), sizePx, sizePx, seconds, where));
        return new Timed(xyz, seconds);
    }

    private static Path secondsFile(Path map) {
        return map.resolveSibling(map.getFileName() + ".seconds");
    }

    private static double cachedSeconds(Path map) {
        try {
            return Double.parseDouble(Files.readString(secondsFile(map)).trim());
        } catch (IOException | NumberFormatException e) {
            return Double.NaN;
        }
    }
}
