package diffract.app;

import diffract.optics.BakedGrid;
import diffract.optics.BrdfSettings;
import diffract.optics.ExactSpectrum;
import diffract.optics.HeightField;
import diffract.optics.LobeSumTable;
import diffract.optics.LobeWeightTable;
import diffract.optics.Variant;
import diffract.util.MemoryEstimate;

import java.util.Locale;

/**
 * The heap a command will need, estimated from the layers' own estimates and checked against the Java heap before
 * any work: what does not fit is refused with the estimate and the options that make it smaller.
 */
final class MemoryCheck {
    /** The map's own buffers per pixel: XYZ, display and linear RGB (3 floats each), luminance, the PNG's pixel. */
    static final int MAP_BYTES_PER_PIXEL = 44;

    private MemoryCheck() {
    }

    /**
     * {@code brdfmap}: the map's buffers, and the reference's exact spectrum, the Taylor terms or the baked
     * table, whichever the variant keeps in the heap.
     */
    static void brdfMap(HeightField field, BrdfSettings settings, int sizePx, double thetaIDeg, Double lambdaNm) {
        long samples = (long) field.rows() * field.cols();
        int termCount = settings.taylor().highestOrder() + 1;
        MemoryEstimate estimate = MemoryEstimate.of(sizePx + "x" + sizePx + " map",
                (long) MAP_BYTES_PER_PIXEL * sizePx * sizePx);
        String wayOut;
        if (settings.variant() == Variant.REFERENCE) {
            double from = lambdaNm != null ? lambdaNm : settings.spectral().lambdaMinNm();
            double to = lambdaNm != null ? lambdaNm : settings.spectral().lambdaMaxNm();
            estimate.plus(ExactSpectrum.memory(field, thetaIDeg, from, to));
            long terms = 8L * samples * termCount;
            wayOut = String.format(Locale.ROOT, "crop the patch (memory grows with its samples and its height), or"
                    + " use --variant flss (its %d terms take %s)", termCount, MemoryEstimate.size(terms));
        } else {
            estimate.plus(termCount + " Taylor terms", 8L * samples * termCount);
            wayOut = "use fewer --terms or crop the patch";
            if (settings.variant() == Variant.LOBES || settings.variant() == Variant.BAKED) {
                // the lobes method's weights per texel over the phase (the baked table bakes the lobes method)
                estimate.plus("the lobes' weight table", LobeWeightTable.bytes(field.rows(), field.cols(),
                        field.maxAbsHeightUm(), settings.spectral().lambdaMinNm(), settings.lobes().weightTolerance()));
                if (LobeSumTable.applies(settings.coherenceWindow(), settings.lobes(), field.widthUm(),
                        field.heightExtentUm())) {
                    estimate.plus("the lobes' texel sums", LobeSumTable.bytes(field.rows(), field.cols(),
                            LobeWeightTable.samples(field.maxAbsHeightUm(), settings.spectral().lambdaMinNm(),
                                    settings.lobes().weightTolerance()),
                            settings.coherenceWindow().sigmaTexels(field.widthUm()),
                            settings.coherenceWindow().sigmaTexels(field.heightExtentUm())));
                }
            }
            if (settings.variant() == Variant.BAKED) {
                BakedGrid grid = BakedGrid.of(settings, field.maxAbsHeightUm());
                estimate.plus(String.format(Locale.ROOT, "baked table %d x %d x %d", grid.uvSamples(),
                        grid.uvSamples(), grid.wSamples()), grid.bytes(12));
                wayOut = "use fewer --baked-samples, fewer --terms or crop the patch";
            }
        }
        if (sizePx > 1024) {
            wayOut = "a smaller --size, or " + wayOut;
        }
        estimate.require(String.format(Locale.ROOT, "the %s map of a %dx%d patch", settings.variant().label(),
                field.cols(), field.rows()), wayOut);
    }

    /** {@code export --mitsuba}: the table's floats, the Taylor terms and the lobes' weight table. */
    static void export(HeightField field, BrdfSettings settings, BakedGrid grid) {
        int termCount = settings.taylor().highestOrder() + 1;
        MemoryEstimate estimate = MemoryEstimate.of(String.format(Locale.ROOT, "table %d x %d x %d", grid.uvSamples(),
                grid.uvSamples(), grid.wSamples()), grid.bytes(12))
                .plus(termCount + " Taylor terms", 8L * field.rows() * field.cols() * termCount)
                .plus("the lobes' weight table", LobeWeightTable.bytes(field.rows(), field.cols(),
                        field.maxAbsHeightUm(), settings.spectral().lambdaMinNm(), settings.lobes().weightTolerance()));
        estimate.require(String.format(Locale.ROOT, "the table of a %dx%d patch", field.cols(), field.rows()),
                "use fewer --baked-samples, fewer --terms or crop the patch");
    }
}
