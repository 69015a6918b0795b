package diffract.optics;

import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;
import diffract.optics.settings.TermFormat;

/**
 * What the GPU variants keep in textures: the Taylor terms' storage, and the baked variant's table resolution.
 *
 * @param termFormat     the term texture's format
 * @param bakedUvSamples BAKED: samples along u and along v over [-2, 2]; 0 = automatic ({@link BakedGrid#automaticUvSamples})
 * @param bakedWSamples  BAKED: samples along w over [-2, 0]; 0 = automatic ({@link BakedGrid#automaticWSamples})
 */
public record GpuTableSettings(TermFormat termFormat, int bakedUvSamples, int bakedWSamples) {
    public GpuTableSettings {
        if (termFormat == null) {
            throw new IllegalArgumentException("the term format is required (RG32F by default)");
        }
        for (int samples : new int[] {bakedUvSamples, bakedWSamples}) {
            if (samples != 0 && (samples < 2 || samples > BakedGrid.MAX_SAMPLES)) {
                throw new InvalidSettingException(Quantity.BAKED_SAMPLES, Quantity.BAKED_SAMPLES.words()
                        + " must be 0 (automatic) or 2.." + BakedGrid.MAX_SAMPLES + " per axis, got " + samples);
            }
        }
    }

    /** Float32 terms, the automatic baked grid. */
    public static GpuTableSettings exact() {
        return new GpuTableSettings(TermFormat.RG32F, 0, 0);
    }
}
