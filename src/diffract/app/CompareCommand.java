package diffract.app;

import diffract.app.options.QuietOption;
import diffract.colour.Srgb;
import diffract.colour.Xyz;
import diffract.optics.maps.BrdfMapDifference;
import diffract.util.ImageFiles;
import diffract.util.UserInputException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.concurrent.Callable;

/** {@code diffract compare}: CIEDE2000 between two colour BRDF maps written by {@code brdfmap --pfm}. */
@Command(name = "compare", mixinStandardHelpOptions = true)
final class CompareCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "A.pfm", descriptionKey = "first-map") Path first;

    @Parameters(index = "1", paramLabel = "B.pfm", descriptionKey = "second-map") Path second;

    @Option(names = "--exposure", defaultValue = "1", paramLabel = "E") double exposure;

    @Mixin QuietOption quiet; // compare prints only its result; accepted like everywhere

    @Override
    public Integer call() throws IOException {
        if (!(exposure > 0) || !Double.isFinite(exposure)) {
            throw new UserInputException("--exposure must be a positive number, got " + exposure);
        }
        int[] a = new int[3];
        int[] b = new int[3];
        float[] mapA = readXyz(first, a);
        float[] mapB = readXyz(second, b);
        if (!Arrays.equals(a, b) || a[0] != a[1]) {
            throw new UserInputException("the maps must be square and of one size: " + a[0] + "x" + a[1] + " and "
                    + b[0] + "x" + b[1]);
        }
        System.out.println(BrdfMapDifference.of(mapA, mapB, a[0], exposure).summary());
        return 0;
    }

    /** The PFM's linear sRGB turned back into XYZ. */
    private static float[] readXyz(Path file, int[] whc) throws IOException {
        if (!Files.isRegularFile(file)) {
            throw new UserInputException("no such file: " + file);
        }
        float[] rgb;
        try {
            rgb = ImageFiles.readPfm(file, whc);
        } catch (IOException e) {
            throw new UserInputException(file + ": " + e.getMessage() + "; compare reads the float maps brdfmap writes"
                    + " with --pfm MAP.pfm", e);
        }
        if (whc[2] != 3) {
            throw new UserInputException(file + " is a grey PFM; compare needs colour maps (brdfmap without --lambda)");
        }
        float[] xyz = new float[rgb.length];
        for (int p = 0; p < rgb.length; p += 3) {
            Xyz c = Srgb.xyzFromLinear(new double[] {rgb[p], rgb[p + 1], rgb[p + 2]});
            xyz[p] = (float) c.x();
            xyz[p + 1] = (float) c.y();
            xyz[p + 2] = (float) c.z();
        }
        return xyz;
    }
}
