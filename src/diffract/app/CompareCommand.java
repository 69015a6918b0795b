package diffract.app;

import diffract.colour.DeltaEStatistics;
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
import java.util.Locale;
import java.util.concurrent.Callable;

/** {@code diffract compare}: CIEDE2000 between two colour BRDF maps written with {@code brdfmap --pfm}. */
@Command(name = "compare", mixinStandardHelpOptions = true,
        description = {"CIEDE2000 between two colour PFMs of linear sRGB (e.g. a variant's BRDF map and the reference's),",
                "over the pixels inside the BRDF map's unit disk, after the same exposure for both."})
final class CompareCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "A.pfm")
    Path a;

    @Parameters(index = "1", paramLabel = "B.pfm")
    Path b;

    @Option(names = "--exposure", defaultValue = "1", paramLabel = "E",
            description = "Scale both maps before comparing, as for display (default ${DEFAULT-VALUE}).")
    double exposure;

    @Override
    public Integer call() throws IOException {
        if (!(exposure > 0)) {
            throw new UserInputException("--exposure must be > 0, got " + exposure);
        }
        int[] sizeA = new int[3];
        int[] sizeB = new int[3];
        float[] rgbA = read(a, sizeA);
        float[] rgbB = read(b, sizeB);
        if (sizeA[0] != sizeB[0] || sizeA[1] != sizeB[1]) {
            throw new UserInputException(a + " is " + sizeA[0] + "x" + sizeA[1] + " but " + b + " is " + sizeB[0] + "x" + sizeB[1]);
        }
        int width = sizeA[0];
        int height = sizeA[1];
        boolean[] insideDisk = new boolean[width * height];
        for (int j = 0; j < height; j++) {
            for (int i = 0; i < width; i++) {
                double x = BrdfMap.xOf(i, width);
                double y = BrdfMap.yOf(j, height);
                insideDisk[j * width + i] = width != height || x * x + y * y < 1;
            }
        }
        DeltaEStatistics stats = DeltaEStatistics.of(toXyz(rgbA), toXyz(rgbB), insideDisk);
        System.out.printf(Locale.ROOT, "CIEDE2000 over %d pixels: mean %.3f, p95 %.3f, p99 %.3f, max %.3f%n",
                stats.pixels(), stats.mean(), stats.p95(), stats.p99(), stats.max());
        return 0;
    }

    private float[] toXyz(float[] rgb) {
        float[] xyz = new float[rgb.length];
        for (int p = 0; p < rgb.length; p += 3) {
            Xyz c = Srgb.xyzFromLinear(new double[] {rgb[p] * exposure, rgb[p + 1] * exposure, rgb[p + 2] * exposure});
            xyz[p] = (float) c.x();
            xyz[p + 1] = (float) c.y();
            xyz[p + 2] = (float) c.z();
        }
        return xyz;
    }

    private static float[] read(Path file, int[] size) throws IOException {
        if (!Files.isRegularFile(file)) {
            throw new UserInputException("no such file: " + file);
        }
        float[] pixels;
        try {
            pixels = ImageFiles.readPfm(file, size);
        } catch (RuntimeException e) {
            throw new UserInputException(file + " is not a PFM image (" + e.getMessage() + ")", e);
        }
        if (size[2] != 3) {
            throw new UserInputException(file + " is a grey PFM; compare needs colour maps (brdfmap without --lambda)");
        }
        return pixels;
    }
}
