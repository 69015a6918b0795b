package diffract.precompute;

import com.fasterxml.jackson.annotation.JsonInclude;

import java.util.List;

/**
 * {@code diffract.json}: what a thesis-format folder written by diffract adds to the script's files, so that
 * reading it back loses nothing. Folders from the original script have no such file; the reader then detects the
 * height unit and estimates max|h| (see {@link ThesisFormat#read}).
 *
 * @param heightUnit     always "um": diffract writes the extrema of term n in micrometres^n
 * @param source         the height field the terms came from (informative)
 * @param patchSha256    {@link diffract.optics.patches.HeightField#contentSha256()} of the mean-subtracted field, or
 *                       null when the terms were converted from a folder without it
 * @param maxHeightUm    the user's --max-height, or null
 * @param maxAbsHeightUm max |h| after mean subtraction, exact
 * @param extrema        the exact double extrema the normalisation used (extrema.txt has them to 35 decimals only)
 */
@JsonInclude(JsonInclude.Include.NON_NULL)
public record ThesisExtras(
        String format,
        int formatVersion,
        String toolVersion,
        String heightUnit,
        String source,
        String patchSha256,
        int rows,
        int cols,
        double pixelSizeXUm,
        double pixelSizeYUm,
        Double maxHeightUm,
        double maxAbsHeightUm,
        int highestOrder,
        List<TermExtrema> extrema) {

    public static final String FORMAT = "diffract-thesis-extras";
    public static final int FORMAT_VERSION = 1;
    public static final String MICROMETRES = "um";

    /** Term n's eq. 1.1 mapping in micrometres^n, guards applied: v = (x - min) / range. */
    public record TermExtrema(int n, double reMin, double reRange, double imMin, double imRange) {
    }
}
