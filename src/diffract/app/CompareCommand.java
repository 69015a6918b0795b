package diffract.app;

import diffract.colour.Ciede2000;
import diffract.colour.D65;
import diffract.colour.Lab;
import diffract.colour.Srgb;
import diffract.colour.Xyz;
import diffract.optics.BrdfMap;
import diffract.util.ImageFiles;
import diffract.util.UserInputException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.concurrent.Callable;

/** {@code diffract compare}: CIEDE2000 between two colour BRDF maps written by {@code brdfmap --pfm}. */
@Command(name = "compare", mixinStandardHelpOptions = true,
        description = {"CIEDE2000 between two colour BRDF maps (the linear sRGB PFMs of brdfmap --pfm), pixel by pixel",
                "inside the unit disk: both are turned back into XYZ, multiplied by the same exposure and converted",
                "to L*a*b* with the D65 white. Prints mean, 95th and 99th percentile and maximum, over the whole disk",
                "and over the lit pixels (exposed Y above 1 % of white in either map)."})
final class CompareCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "A.pfm")
    Path first;

    @Parameters(index = "1", paramLabel = "B.pfm")
    Path second;

    @Option(names = "--exposure", defaultValue = "1", paramLabel = "E",
            description = "Multiplies both maps' XYZ before L*a*b* (use the exposure the pictures were shown with).")
    double exposure;

    @Override
    public Integer call() throws IOException {
        if (!(exposure > 0) || !Double.isFinite(exposure)) {
            throw new UserInputException("--exposure must be a positive number, got " + exposure);
        }
        int[] a = new int[3];
        int[] b = new int[3];
        float[] mapA = read(first, a);
        float[] mapB = read(second, b);
        if (!Arrays.equals(a, b) || a[0] != a[1]) {
            throw new UserInputException("the maps must be square and of one size: " + a[0] + "x" + a[1] + " and "
                    + b[0] + "x" + b[1]);
        }
        int size = a[0];
        Xyz white = D65.whiteXyz();
        double[] delta = new double[size * size];
        double[] litDelta = new double[size * size];
        int n = 0;
        int lit = 0;
        for (int j = 0; j < size; j++) {
            for (int i = 0; i < size; i++) {
                double x = BrdfMap.xOf(i, size);
                double y = BrdfMap.yOf(j, size);
                if (x * x + y * y >= 1) {
                    continue;
                }
                int p = 3 * (j * size + i);
                Xyz colourA = xyz(mapA, p);
                Xyz colourB = xyz(mapB, p);
                double d = Ciede2000.deltaE(Lab.fromXyz(colourA, white), Lab.fromXyz(colourB, white));
                delta[n++] = d;
                if (Math.max(colourA.y(), colourB.y()) > LIT_Y) {
                    litDelta[lit++] = d;
                }
            }
        }
        System.out.printf(Locale.ROOT, "CIEDE2000 %s over %d pixels; lit: %s over %d pixels (exposure %s)%n",
                statistics(Arrays.copyOf(delta, n)), n, statistics(Arrays.copyOf(litDelta, lit)), lit, exposure);
        return 0;
    }

    /** A pixel counts as lit when its exposed Y exceeds 1 % of white (L* above 9). */
    static final double LIT_Y = 0.01;

    private static String statistics(double[] d) {
        if (d.length == 0) {
            return "mean -, p95 -, p99 -, max -";
        }
        Arrays.sort(d);
        double sum = 0;
        for (double v : d) {
            sum += v;
        }
        return String.format(Locale.ROOT, "mean %.3f, p95 %.3f, p99 %.3f, max %.2f", sum / d.length,
                percentile(d, 0.95), percentile(d, 0.99), d[d.length - 1]);
    }

    private Xyz xyz(float[] linearSrgb, int p) {
        return Srgb.xyzFromLinear(new double[] {linearSrgb[p], linearSrgb[p + 1], linearSrgb[p + 2]}).scaled(exposure);
    }

    private static float[] read(Path file, int[] whc) throws IOException {
        if (!Files.isRegularFile(file)) {
            throw new UserInputException("no such file: " + file);
        }
        float[] map = ImageFiles.readPfm(file, whc);
        if (whc[2] != 3) {
            throw new UserInputException(file + " is not a colour PFM (monochromatic maps have no colour difference)");
        }
        return map;
    }

    /** Nearest rank. */
    static double percentile(double[] sorted, double q) {
        int rank = (int) Math.ceil(q * sorted.length) - 1;
        return sorted[Math.max(0, Math.min(sorted.length - 1, rank))];
    }
}
