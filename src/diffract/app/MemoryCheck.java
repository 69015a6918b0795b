package diffract.app;

import diffract.optics.BakedGrid;
import diffract.optics.BrdfSettings;
import diffract.optics.patches.HeightField;
import diffract.optics.Methods;
import diffract.optics.lobes.LobeWeightTable;
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
        Variant method = settings.variant();
        double from = lambdaNm != null ? lambdaNm : settings.spectral().lambdaMinNm();
        double to = lambdaNm != null ? lambdaNm : settings.spectral().lambdaMaxNm();
        MemoryEstimate estimate = MemoryEstimate.of(sizePx + "x" + sizePx + " map",
                (long) MAP_BYTES_PER_PIXEL * sizePx * sizePx)
                .plus(method.heapMemory(field, settings, thetaIDeg, from, to));
        String wayOut;
        if (!method.runsOnGpu()) {
            Variant thesis = Methods.Role.THESIS.method();
            wayOut = String.format(Locale.ROOT, "crop the patch (memory grows with its samples and its height), or"
                    + " use --variant %s (its %d terms take %s)", thesis.label(), settings.taylor().highestOrder() + 1,
                    MemoryEstimate.size(thesis.heapMemory(field, settings, thetaIDeg, from, to).bytes()));
        } else if (method.drawsTable()) {
            wayOut = "use fewer --baked-samples, fewer --terms or crop the patch";
        } else {
            wayOut = "use fewer --terms or crop the patch";
        }
        if (sizePx > 1024) {
            wayOut = "a smaller --size, or " + wayOut;
        }
        estimate.require(String.format(Locale.ROOT, "the %s map of a %dx%d patch", method.spec(),
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
