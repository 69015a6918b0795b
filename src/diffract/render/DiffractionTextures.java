package diffract.render;

import diffract.colour.Cie1931;
import diffract.colour.D65;
import diffract.colour.MirrorNormalisation;
import diffract.colour.SpectralIntegrator;
import diffract.colour.Trapezoid;
import diffract.jrtr.textures.FloatTexture1D;
import diffract.jrtr.textures.FloatTextureArray;
import diffract.optics.BrdfSettings;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.lobes.LobeWeightTable;
import diffract.optics.spectra.PhaseCentredTerms;
import diffract.optics.spectra.PhaseCentres;
import diffract.optics.settings.Quantity;
import diffract.optics.settings.SpectralSettings;
import diffract.optics.TaylorEvaluation;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.settings.TermFormat;
import diffract.optics.Variant;
import diffract.optics.windows.WindowRadii;
import diffract.util.Reporter;

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
 *   <li>{@code spectralTable}: D65 x CIE 1931 at 1 nm over the CMF table's 360..830 nm, (f S xbar, f S ybar,
 *       f S zbar, S ybar) with the mirror's factor f ({@link MirrorNormalisation}; the normaliser sums S ybar),
 *       for NMM's arbitrary wavelengths (interpolated linearly in the shader; the CPU interpolates S and the CMF
 *       separately and multiplies, which differs by less than 1e-4 relative at 1 nm spacing);</li>
 *   <li>the baked tables ({@link TableTextures}): the baked method's, baked once per patch and settings
 *       ({@link BakedTables}), and the lobes method's for wide environment lights;</li>
 *   <li>the lobes method's tables ({@link LobeTextures}, made on first use).</li>
 * </ul>
 *
 * <p>The terms are stored in the settings' {@link TermFormat}. Only what the settings need goes to the GPU: with a
 * Taylor tolerance only the terms up to
 * {@link BrdfSettings#highestOrderNeeded} (no fragment's loop reaches further), and only the uniform-grid nodes
 * where D65 x CMF is not zero in all three channels (they would add 0 x |P|^2).
 */
public final class DiffractionTextures {
    private final FloatTextureArray terms;
    private final FloatTexture1D termExtrema;
    private final FloatTexture1D uniformNodeTable;
    private final FloatTexture1D spectralTable;
    private final double spectralTableFirstNm;
    private final double extentXUm;
    private final double extentYUm;
    private final int highestOrder;
    private final WindowRadii windowRadii;
    private final double maxAbsHeightUm;
    private final TableTextures tables;
    private final PhaseCentres phaseCentres;
    private final LobeTextures lobes;

    private DiffractionTextures(FloatTextureArray terms, FloatTexture1D termExtrema, FloatTexture1D uniformNodeTable,
                                FloatTexture1D spectralTable, double spectralTableFirstNm, TaylorTerms source,
                                BrdfSettings settings, int highestOrder, TableTextures tables, PhaseCentres phaseCentres,
                                java.util.function.BiFunction<Double, Double, LobeWeightTable> lobeWeightSource) {
        this.terms = terms;
        this.termExtrema = termExtrema;
        this.uniformNodeTable = uniformNodeTable;
        this.spectralTable = spectralTable;
        this.spectralTableFirstNm = spectralTableFirstNm;
        this.extentXUm = source.cols() * source.pixelSizeXUm();
        this.extentYUm = source.rows() * source.pixelSizeYUm();
        this.highestOrder = highestOrder;
        this.windowRadii = settings.windowRadii(extentXUm, extentYUm);
        this.maxAbsHeightUm = source.maxAbsHeightUm();
        this.tables = tables;
        this.phaseCentres = phaseCentres;
        this.lobes = new LobeTextures(lobeWeightSource, extentXUm, extentYUm);
    }

    /**
     * The textures of the path {@link TaylorEvaluation#choose} picked: the thesis' terms or the phase-centred ones; a
     * baked table comes from {@code tables} (the pipeline's), baked there first if it is not at hand.
     */
    public static DiffractionTextures of(TaylorEvaluation evaluation, BrdfSettings settings, BakedTables tables,
                                         Reporter reporter) {
        DiffractionTextures t = evaluation.isPhaseCentred() ? ofPhaseCentred(evaluation.centredTerms(), settings)
                : of(evaluation.plainTerms(), settings, tables, reporter);
        evaluation.orders().ifPresent(t.lobes()::useOrders);
        return t;
    }

    /** Terms 0..N (which the terms must hold) and the tables for the settings' wavelengths. */
    public static DiffractionTextures of(TaylorTerms terms, BrdfSettings settings) {
        return of(terms, settings, Reporter.SILENT);
    }

    /**
     * As above; a table is baked (or loaded from the disk cache) for these textures alone, with progress on
     * {@code reporter}.
     */
    public static DiffractionTextures of(TaylorTerms terms, BrdfSettings settings, Reporter reporter) {
        return of(terms, settings, new BakedTables(), reporter);
    }

    /** As above, a baked table from {@code tables}, baked there first if it is not at hand. */
    public static DiffractionTextures of(TaylorTerms terms, BrdfSettings settings, BakedTables tables,
                                         Reporter reporter) {
        if (settings.taylor().highestOrder() > terms.highestOrder()) {
            throw new IllegalArgumentException("Taylor order " + settings.taylor().highestOrder()
                    + " requested, the terms hold 0.." + terms.highestOrder());
        }
        int highestOrder = settings.highestOrderNeeded(terms.maxAbsHeightUm());
        FloatTextureArray.Precision precision = TermFormats.precision(settings.gpu().termFormat());
        boolean normalised = precision == FloatTextureArray.Precision.UNORM8;
        List<float[]> layers = new ArrayList<>();
        if (normalised) {
            layers.addAll(NormalisedTerms.layers(terms, highestOrder));
        } else {
            for (int n = 0; n <= highestOrder; n++) {
                layers.add(terms.termData(n));
            }
        }
        FloatTextureArray termTexture = new FloatTextureArray(terms.cols(), terms.rows(), layers, precision);
        BakedTable baked = settings.variant().drawsTable() ? tables.of(terms, settings, reporter) : null;
        return new DiffractionTextures(termTexture, normalised
                ? NormalisedTerms.extremaTable(terms, highestOrder) : null, buildUniformNodeTable(settings.spectral()),
                buildSpectralTable(settings.spectral().normalisation()), Cie1931.firstNm(), terms, settings, highestOrder,
                new TableTextures(baked, r -> tables.of(terms, settings.with(b -> b.drawnBy(Variant.BAKED)), r)), null,
                (lambdaMinNm, tolerance) -> LobeWeightTable.ofTerms(terms, highestOrder, lambdaMinNm, tolerance));
    }

    /**
     * The phase-centred expansion: every centre's terms E_{j,n} in layer j * (N_c + 1) + n
     * ({@link PhaseCentredTerms#layers()}, read by {@code taylor_centred.glsl}); the settings' Taylor order does not
     * apply, the centres fix theirs.
     */
    public static DiffractionTextures ofPhaseCentred(PhaseCentredTerms terms, BrdfSettings settings) {
        if (settings.variant().drawsTable()) {
            throw new InvalidSettingException(Quantity.VARIANT, "the baked table tabulates the thesis' series around 0; "
                    + "this patch needs the phase-centred expansion (its phase k w h reaches beyond what that series "
                    + "sums): draw it with the lobes method or flss");
        }
        if (settings.gpu().termFormat() == TermFormat.RG8) {
            throw new InvalidSettingException(Quantity.TERM_FORMAT, "8-bit terms (rg8) hold the thesis' series around"
                    + " 0 only; this patch needs the phase-centred expansion: store the terms as rg32f or rg16f");
        }
        FloatTextureArray.Precision precision = TermFormats.precision(settings.gpu().termFormat());
        TaylorTerms first = terms.aroundCentre(0);
        FloatTextureArray termTexture = new FloatTextureArray(terms.cols(), terms.rows(), terms.layers(), precision);
        return new DiffractionTextures(termTexture, null, buildUniformNodeTable(settings.spectral()),
                buildSpectralTable(settings.spectral().normalisation()), Cie1931.firstNm(), first, settings,
                terms.centres().highestOrder(), new TableTextures(null, null), terms.centres(),
                (lambdaMinNm, tolerance) -> LobeWeightTable.ofTerms(terms, lambdaMinNm, tolerance));
    }

    /**
     * (wx, wy, wz, lambda) per node of WavelengthSampling.uniform(min, max, step), leaving out the nodes whose
     * three weights are all 0 (outside the CMF or D65 tables): the shader's loop runs over the rest only.
     */
    static FloatTexture1D buildUniformNodeTable(SpectralSettings spectral) {
        return buildUniformNodeTable(spectral.lambdaMinNm(), spectral.lambdaMaxNm(), spectral.lambdaStepNm(),
                spectral.normalisation());
    }

    /** As above for any grid (wavelengths outside the colour tables included). */
    static FloatTexture1D buildUniformNodeTable(double lambdaMinNm, double lambdaMaxNm, double lambdaStepNm,
                                                MirrorNormalisation normalisation) {
        double[] nodes = Trapezoid.uniformNodes(lambdaMinNm, lambdaMaxNm, lambdaStepNm);
        double[][] weights = SpectralIntegrator.xyzWeights(nodes, Trapezoid.weights(nodes), normalisation);
        float[] rgba = new float[4 * nodes.length];
        int kept = 0;
        for (int j = 0; j < nodes.length; j++) {
            if (weights[j][0] == 0 && weights[j][1] == 0 && weights[j][2] == 0) {
                continue;
            }
            rgba[4 * kept] = (float) weights[j][0];
            rgba[4 * kept + 1] = (float) weights[j][1];
            rgba[4 * kept + 2] = (float) weights[j][2];
            rgba[4 * kept + 3] = (float) nodes[j];
            kept++;
        }
        if (kept == 0) {
            throw new InvalidSettingException(Quantity.LAMBDA_MIN, "no wavelength in " + lambdaMinNm + ".."
                    + lambdaMaxNm + " nm has a non-zero CIE 1931 x D65 weight");
        }
        return new FloatTexture1D(java.util.Arrays.copyOf(rgba, 4 * kept));
    }

    /**
     * D65 x CMF times the mirror's factor ({@link MirrorNormalisation#factor}) at every nm of the CMF table (outside
     * it the CMFs are 0, as on the CPU).
     */
    static FloatTexture1D buildSpectralTable(MirrorNormalisation normalisation) {
        int first = (int) Math.round(Cie1931.firstNm());
        int last = (int) Math.round(Cie1931.lastNm());
        float[] rgba = new float[4 * (last - first + 1)];
        for (int lambda = first; lambda <= last; lambda++) {
            double s = D65.relativePower(lambda) * normalisation.factor(lambda);
            int i = 4 * (lambda - first);
            rgba[i] = (float) (s * Cie1931.xBar(lambda));
            rgba[i + 1] = (float) (s * Cie1931.yBar(lambda));
            rgba[i + 2] = (float) (s * Cie1931.zBar(lambda));
            rgba[i + 3] = (float) (D65.relativePower(lambda) * Cie1931.yBar(lambda)); // the normaliser's integrand
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

    /** The lobes method's tables, made on first use from these terms. */
    public LobeTextures lobes() {
        return lobes;
    }

    /** The phase centres of a phase-centred term array, null for the thesis' terms around 0. */
    public PhaseCentres phaseCentres() {
        return phaseCentres;
    }

    /** The highest Taylor order uploaded (BrdfSettings.highestOrderNeeded, or the centres' order): TAYLOR_HIGHEST_ORDER of the shaders. */
    public int highestOrder() {
        return highestOrder;
    }

    /** The window radii per axis (fixed, or automatic from sigma_f). */
    public WindowRadii windowRadii() {
        return windowRadii;
    }

    /** max|h| of the patch in um, for each fragment's early stop. */
    public double maxAbsHeightUm() {
        return maxAbsHeightUm;
    }

    /** The baked tables: the baked method's (BAKED only) and the lobes method's for wide environment lights. */
    public TableTextures tables() {
        return tables;
    }

    /** The baked method's table (BAKED only), else null: {@code tables().baked()}. */
    public BakedTable baked() {
        return tables.baked();
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
