package diffract.pipeline;

import diffract.optics.OrderCorrection;
import diffract.optics.settings.OrderWeights;
import diffract.util.DiskCache;

import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.HeightField;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.spectra.PhaseCentredTerms;
import diffract.optics.settings.Quantity;
import diffract.optics.TaylorEvaluation;
import diffract.optics.spectra.TaylorTerms;
import diffract.precompute.Precomputation;
import diffract.precompute.TaylorTermComputer;
import diffract.render.BakedTables;
import diffract.render.DiffractionTextures;
import diffract.render.GpuBrdfMap;
import diffract.util.Reporter;

import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The one path from a height field to a picture, which every command takes: a patch and {@link BrdfSettings} become
 * Taylor terms (from the user cache, computed on first use, or from a folder), the expansion that sums them (the
 * thesis' series, or the phase-centred expansion where float32 cannot reach the series' accuracy:
 * {@link TaylorEvaluation#choose}), and then either the CPU's {@link DiffractionBrdf} or the GPU's textures and
 * materials ({@link DiffractionTextures}, {@link GpuBrdfMap}) in the settings' term format.
 *
 * <p>The phase-centred terms depend only on the patch and the shortest wavelength, so they are computed once per
 * wavelength and kept. Thread-safe.
 */
public final class DiffractionPipeline {
    private final NamedPatch patch;
    private final TermSource termSource;
    private final Map<Double, PhaseCentredTerms> centredByShortestLambda = new ConcurrentHashMap<>();
    private final BakedTables tables = new BakedTables();

    public DiffractionPipeline(NamedPatch patch, TermSource termSource) {
        this.patch = patch;
        this.termSource = termSource;
    }

    /** Terms from the user cache, keyed by the patch's content and N, precomputed on first use. */
    public static DiffractionPipeline cached(NamedPatch patch, double lambdaMinNm) {
        return new DiffractionPipeline(patch, (n, reporter) -> Precomputation.cached(new Precomputation.Request(
                patch.meanSubtracted(), patch.name(), patch.maxHeightUm(), n, null, lambdaMinNm), reporter));
    }

    /**
     * Terms given (e.g. read from a folder): they must belong to this patch (same grid and pixel size) and hold
     * the orders asked for.
     *
     * @param origin where the terms came from, for messages
     */
    public static DiffractionPipeline withTerms(NamedPatch patch, TaylorTerms terms, String origin) {
        requireSamePatch(terms, patch.meanSubtracted(), origin);
        return new DiffractionPipeline(patch, (n, reporter) -> {
            if (terms.highestOrder() < n) {
                throw new InvalidSettingException(Quantity.HIGHEST_ORDER, origin + " holds terms 0.."
                        + terms.highestOrder() + " but N = " + n + " was asked; ask for N = "
                        + terms.highestOrder() + " or precompute more");
            }
            return terms;
        });
    }

    public NamedPatch patch() {
        return patch;
    }

    /** The patch's baked tables: baked (or loaded from the disk cache) once, kept while the pipeline lives. */
    public BakedTables tables() {
        return tables;
    }

    /** Terms 0..N (or more) of the patch. */
    public TaylorTerms terms(int highestOrder, Reporter reporter) {
        return termSource.terms(highestOrder, reporter);
    }

    /**
     * The expansion the settings ask for over these terms ({@link TaylorEvaluation#choose}), with the centred terms
     * computed once per shortest wavelength.
     *
     * @param shortestLambdaNm the shortest wavelength drawn (the spectral range's, or a monochromatic map's if shorter)
     */
    public TaylorEvaluation evaluation(BrdfSettings settings, TaylorTerms terms, double shortestLambdaNm,
                                       Reporter reporter) {
        TaylorEvaluation e = TaylorEvaluation.choose(settings.taylor().expansion(), patch.meanSubtracted(), terms,
                settings.taylor().highestOrder(), shortestLambdaNm, (field, centres) ->
                        centredByShortestLambda.computeIfAbsent(shortestLambdaNm,
                                lambda -> TaylorTermComputer.computeCentred(field, centres, reporter)), reporter);
        return settings.rigorous().orders() == OrderWeights.RIGOROUS
                ? e.withOrders(OrderCorrection.of(patch.meanSubtracted(), settings, DiskCache.user(), reporter)) : e;
    }

    /** As above with the terms of N from the term source. */
    public TaylorEvaluation evaluation(BrdfSettings settings, double shortestLambdaNm, Reporter reporter) {
        return evaluation(settings, terms(settings.taylor().highestOrder(), reporter), shortestLambdaNm, reporter);
    }

    /** The CPU BRDF: the exact reference on the height field itself, a Taylor variant on its evaluation. */
    public DiffractionBrdf cpuBrdf(BrdfSettings settings, double shortestLambdaNm, Reporter reporter) {
        if (!settings.variant().readsTerms()) {
            return DiffractionBrdf.create(settings, patch.meanSubtracted(), null);
        }
        return evaluation(settings, shortestLambdaNm, reporter).brdf(settings, patch.meanSubtracted());
    }

    /** A GPU BRDF map (a hidden GL context: close it) on the path the settings ask for. */
    public GpuBrdfMap gpuMap(BrdfSettings settings, double shortestLambdaNm, Reporter reporter) {
        return new GpuBrdfMap(evaluation(settings, shortestLambdaNm, reporter), settings, tables, reporter);
    }

    /**
     * The GPU textures for these settings over the terms at hand (a viewer draws with the terms it has while more
     * are computed): the settings' N must not exceed the terms'.
     */
    public DiffractionTextures textures(BrdfSettings settings, TaylorTerms termsAtHand, Reporter reporter) {
        TaylorEvaluation e = evaluation(settings, termsAtHand, settings.spectral().lambdaMinNm(), reporter);
        return DiffractionTextures.of(e, settings, tables, reporter);
    }

    /** Terms from another patch would render a different surface than the one named: refuse them. */
    private static void requireSamePatch(TaylorTerms terms, HeightField field, String origin) {
        boolean sameGrid = terms.rows() == field.rows() && terms.cols() == field.cols();
        boolean samePixels = Math.abs(terms.pixelSizeXUm() / field.pixelSizeXUm() - 1) < 1e-4
                && Math.abs(terms.pixelSizeYUm() / field.pixelSizeYUm() - 1) < 1e-4;
        if (!sameGrid || !samePixels) {
            throw new diffract.util.UserInputException(String.format(Locale.ROOT,
                    "%s was made from a %dx%d patch of %.4g x %.4g um pixels, but the patch is %dx%d of %.4g x %.4g um;"
                            + " precompute the terms of this patch", origin, terms.cols(), terms.rows(),
                    terms.pixelSizeXUm(), terms.pixelSizeYUm(), field.cols(), field.rows(),
                    field.pixelSizeXUm(), field.pixelSizeYUm()));
        }
    }
}
