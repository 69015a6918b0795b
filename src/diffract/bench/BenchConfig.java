package diffract.bench;

import diffract.jrtr.FloatTextureArray;
import diffract.optics.BrdfSettings;
import diffract.render.TermFormats;

import java.util.Locale;

/**
 * One configuration of the sweep: a patch, the variant's settings, how the terms are stored and the map size.
 *
 * @param textureFormat the CLI name of the term storage: rg32f, rg16f or rg8
 */
public record BenchConfig(String patch, BrdfSettings settings, String textureFormat, int sizePx) {

    /** A stable text key (patch, variant, N, step, R, format, size, tolerance) for caches and duplicate removal. */
    public String key() {
        return String.format(Locale.ROOT, "%s/%s/n%d/step%s/r%s/%s/%d/tol%s", patch,
                settings.variant().cliName(), settings.highestOrder(), Csv.number(settings.lambdaStepNm()),
                windowRadiusLabel(), textureFormat, sizePx, Csv.number(settings.taylorTolerance()));
    }

    /** The window radius R, or "auto" when it follows sigma_f (WindowRadii.automatic). */
    public String windowRadiusLabel() {
        return settings.automaticWindowRadius() ? "auto" : Integer.toString(settings.windowRadius());
    }

    /**
     * The work of one frame in arbitrary units, for the ETA only: pixels x Taylor terms x window texels x
     * wavelengths (the shader's loop nest, 003 Algorithm 3).
     */
    public double workUnits() {
        double wavelengths = (settings.lambdaMaxNm() - settings.lambdaMinNm()) / settings.lambdaStepNm() + 1;
        int window = 2 * settings.windowRadius() + 1;
        return (double) sizePx * sizePx * (settings.highestOrder() + 1) * window * window * wavelengths;
    }

    /** The storage precision on the GPU. */
    public FloatTextureArray.Precision precision() {
        return TermFormats.parse(textureFormat);
    }
}
