package diffract.render;

import diffract.jrtr.textures.FloatTexture1D;
import diffract.jrtr.textures.FloatTextureArray;
import diffract.optics.spectra.TaylorTerms;
import diffract.precompute.ThesisExtrema;

import java.util.ArrayList;
import java.util.List;

/**
 * The thesis' [0, 1]-normalised term storage at 8 bits (003 eq. 1.1): per term n, Re and Im are mapped separately
 * to v = (x - min_n) / range_n with the term's own extrema (the same extrema {@code terms.json} and the thesis'
 * {@code extrema.txt} record, guards of {@link ThesisExtrema.Channel} included), stored as the unsigned normalised
 * byte round(255 v) ({@link FloatTextureArray.Precision#UNORM8}), and de-normalised in the shader's term lookup as
 * x = min_n + (byte / 255) range_n ({@code normalisedTaylorSumAt} in {@code diffraction_common.glsl}, which folds
 * min_n and range_n into the Taylor coefficients once per wavelength). The error of one stored
 * value is at most half a quantisation step, range_n / 510.
 */
public final class NormalisedTerms {
    private NormalisedTerms() {
    }

    /** Term n's mapping of Re and Im, from its extrema. */
    public static ThesisExtrema.Term mapping(TaylorTerms terms, int n) {
        TaylorTerms.Extrema e = terms.extrema(n);
        return new ThesisExtrema.Term(ThesisExtrema.Channel.ofExtrema(e.reMin(), e.reMax()),
                ThesisExtrema.Channel.ofExtrema(e.imMin(), e.imMax()));
    }

    /** Layers 0..highestOrder normalised to [0, 1] (interleaved Re, Im as {@link TaylorTerms#termData}). */
    public static List<float[]> layers(TaylorTerms terms, int highestOrder) {
        List<float[]> layers = new ArrayList<>();
        for (int n = 0; n <= highestOrder; n++) {
            ThesisExtrema.Term map = mapping(terms, n);
            float[] data = terms.termData(n);
            float[] v = new float[data.length];
            for (int i = 0; i < data.length; i += 2) {
                v[i] = map.re().normalise(data[i]);
                v[i + 1] = map.im().normalise(data[i + 1]);
            }
            layers.add(v);
        }
        return layers;
    }

    /** Per term (min Re, min Im, range Re, range Im): what the shader needs to de-normalise, texel n = term n. */
    public static FloatTexture1D extremaTable(TaylorTerms terms, int highestOrder) {
        float[] rgba = new float[4 * (highestOrder + 1)];
        for (int n = 0; n <= highestOrder; n++) {
            ThesisExtrema.Term map = mapping(terms, n);
            rgba[4 * n] = (float) map.re().min();
            rgba[4 * n + 1] = (float) map.im().min();
            rgba[4 * n + 2] = (float) map.re().range();
            rgba[4 * n + 3] = (float) map.im().range();
        }
        return new FloatTexture1D(rgba);
    }

    /**
     * What the shader reads for a stored value x of a channel: min + (round(255 v) / 255) range, in float32 as
     * the shader computes it (the test holds it within half a quantisation step of x).
     */
    public static float decoded(float x, ThesisExtrema.Channel channel) {
        int stored = FloatTextureArray.toUnorm8(channel.normalise(x));
        return (float) channel.min() + (stored / 255.0f) * (float) channel.range();
    }
}
