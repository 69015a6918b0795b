package diffract.render;

import diffract.colour.Cie1931;
import diffract.colour.D65;
import diffract.colour.SpectralIntegrator;
import diffract.colour.Trapezoid;
import diffract.jrtr.FloatTexture1D;
import diffract.jrtr.FloatTextureArray;
import diffract.optics.BrdfSettings;
import diffract.optics.TaylorTerms;

import java.util.ArrayList;
import java.util.List;

/**
 * The data every diffraction material reads, made once per patch and settings and uploaded once (on first use):
 *
 * <ul>
 *   <li>{@code taylorTerms}: DFT_0 .. DFT_N as a texture array, layer n = term n, texel (x = col, y = row) =
 *       (Re, Im), exactly the float32 values of {@link TaylorTerms} with RG32F (RG16F rounds them to half
 *       precision and flushes values below 6e-8 to 0: an option for memory, not for accuracy; UNORM8 stores
 *       the thesis' [0, 1]-normalised bytes of {@link NormalisedTerms}, de-normalised with {@code termExtrema});</li>
 *   <li>{@code uniformNodeTable}: per node of the uniform grid (FLSS, PQ, NMM's fallback) the normalised weights
 *       of {@link SpectralIntegrator#xyzWeights} and the node, (wx, wy, wz, lambda_nm);</li>
 *   <li>{@code spectralTable}: D65 x CIE 1931 at 1 nm over the CMF table's 360..830 nm, (S xbar, S ybar, S zbar, 0),
 *       for NMM's arbitrary wavelengths (interpolated linearly in the shader; the CPU interpolates S and the CMF
 *       separately and multiplies, which differs by less than 1e-4 relative at 1 nm spacing).</li>
 * </ul>
 */
public final class DiffractionTextures {
    private final FloatTextureArray terms;
    private final FloatTexture1D termExtrema;
    private final FloatTexture1D uniformNodeTable;
    private final FloatTexture1D spectralTable;
    private final double spectralTableFirstNm;
    private final double extentXUm;
    private final double extentYUm;

    private DiffractionTextures(FloatTextureArray terms, FloatTexture1D termExtrema, FloatTexture1D uniformNodeTable,
                                FloatTexture1D spectralTable, double spectralTableFirstNm, double extentXUm,
                                double extentYUm) {
        this.terms = terms;
        this.termExtrema = termExtrema;
        this.uniformNodeTable = uniformNodeTable;
        this.spectralTable = spectralTable;
        this.spectralTableFirstNm = spectralTableFirstNm;
        this.extentXUm = extentXUm;
        this.extentYUm = extentYUm;
    }

    /** Terms 0..settings.highestOrder() (which the terms must hold) and the tables for the settings' wavelengths. */
    public static DiffractionTextures of(TaylorTerms terms, BrdfSettings settings, FloatTextureArray.Precision precision) {
        if (settings.highestOrder() > terms.highestOrder()) {
            throw new IllegalArgumentException("Taylor order " + settings.highestOrder() + " requested, the terms hold 0.."
                    + terms.highestOrder());
        }
        boolean normalised = precision == FloatTextureArray.Precision.UNORM8;
        List<float[]> layers = new ArrayList<>();
        if (normalised) {
            layers.addAll(NormalisedTerms.layers(terms, settings.highestOrder()));
        } else {
            for (int n = 0; n <= settings.highestOrder(); n++) {
                layers.add(terms.termData(n));
            }
        }
        FloatTextureArray termTexture = new FloatTextureArray(terms.cols(), terms.rows(), layers, precision);
        return new DiffractionTextures(termTexture,
                normalised ? NormalisedTerms.extremaTable(terms, settings.highestOrder()) : null,
                buildUniformNodeTable(settings), buildSpectralTable(),
                Cie1931.firstNm(), terms.cols() * terms.pixelSizeXUm(), terms.rows() * terms.pixelSizeYUm());
    }

    /** (wx, wy, wz, lambda) per node of WavelengthSampling.uniform(min, max, step). */
    static FloatTexture1D buildUniformNodeTable(BrdfSettings settings) {
        double[] nodes = Trapezoid.uniformNodes(settings.lambdaMinNm(), settings.lambdaMaxNm(), settings.lambdaStepNm());
        double[][] weights = SpectralIntegrator.xyzWeights(nodes, Trapezoid.weights(nodes));
        float[] rgba = new float[4 * nodes.length];
        for (int j = 0; j < nodes.length; j++) {
            rgba[4 * j] = (float) weights[j][0];
            rgba[4 * j + 1] = (float) weights[j][1];
            rgba[4 * j + 2] = (float) weights[j][2];
            rgba[4 * j + 3] = (float) nodes[j];
        }
        return new FloatTexture1D(rgba);
    }

    /** D65 x CMF at every nm of the CMF table (outside it the CMFs are 0, as on the CPU). */
    static FloatTexture1D buildSpectralTable() {
        int first = (int) Math.round(Cie1931.firstNm());
        int last = (int) Math.round(Cie1931.lastNm());
        float[] rgba = new float[4 * (last - first + 1)];
        for (int lambda = first; lambda <= last; lambda++) {
            double s = D65.relativePower(lambda);
            int i = 4 * (lambda - first);
            rgba[i] = (float) (s * Cie1931.xBar(lambda));
            rgba[i + 1] = (float) (s * Cie1931.yBar(lambda));
            rgba[i + 2] = (float) (s * Cie1931.zBar(lambda));
        }
        return new FloatTexture1D(rgba);
    }

    public FloatTextureArray terms() {
        return terms;
    }

    /** Whether the terms are stored [0, 1]-normalised at 8 bits (then {@link #termExtrema()} de-normalises them). */
    public boolean normalisedTerms() {
        return termExtrema != null;
    }

    /** Per term (min Re, min Im, range Re, range Im) of {@link NormalisedTerms}; null unless normalised. */
    public FloatTexture1D termExtrema() {
        return termExtrema;
    }

    public FloatTexture1D uniformNodeTable() {
        return uniformNodeTable;
    }

    public FloatTexture1D spectralTable() {
        return spectralTable;
    }

    public double spectralTableFirstNm() {
        return spectralTableFirstNm;
    }

    /** L_x = cols dH_x in micrometres. */
    public double extentXUm() {
        return extentXUm;
    }

    /** L_y = rows dH_y in micrometres. */
    public double extentYUm() {
        return extentYUm;
    }
}
