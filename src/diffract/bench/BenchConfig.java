package diffract.bench;

import diffract.optics.BrdfSettings;

import java.util.Locale;

/**
 * One configuration of the sweep: a patch, the variant's settings (term format included) and the map size.
 */
public record BenchConfig(String patch, BrdfSettings settings, int sizePx) {

    /** A stable text key (patch, variant, N, step, R, format, size, tolerance) for caches and duplicate removal. */
    public String key() {
        return String.format(Locale.ROOT, "%s/%s/n%d/step%s/r%s/%s/%d/tol%s", patch,
                settings.variant().label(), settings.taylor().highestOrder(),
                Csv.number(settings.spectral().lambdaStepNm()), windowRadiusLabel(), textureFormat(), sizePx,
                Csv.number(settings.taylor().tolerance()));
    }

    /** rg32f, rg16f or rg8. */
    public String textureFormat() {
        return settings.gpu().termFormat().label();
    }

    /** The window radius R, or "auto" when it follows sigma_f (WindowRadii.automatic). */
    public String windowRadiusLabel() {
        return settings.window().automatic() ? "auto" : Integer.toString(settings.window().radius());
    }

    /**
     * The work of one frame in arbitrary units, for the ETA only: pixels x Taylor terms x window texels x
     * wavelengths (the shader's loop nest, 003 Algorithm 3).
     */
    public double workUnits() {
        double wavelengths = (settings.spectral().lambdaMaxNm() - settings.spectral().lambdaMinNm())
                / settings.spectral().lambdaStepNm() + 1;
        int window = 2 * settings.window().radius() + 1;
        return (double) sizePx * sizePx * (settings.taylor().highestOrder() + 1) * window * window * wavelengths;
    }
}
