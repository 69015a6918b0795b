package diffract.precompute;

import com.fasterxml.jackson.annotation.JsonInclude;

import java.util.List;

/**
 * The JSON sidecar {@code terms.json} of a precomputed term set (see {@link TermStore} for the binary layout).
 * Everything needed to trust and use the data: which patch (content hash), which parameters, which checksum.
 */
@JsonInclude(JsonInclude.Include.NON_NULL)
public record TermSidecar(
        String format,
        int formatVersion,
        String toolVersion,
        Patch patch,
        int highestOrder,
        int termCount,
        Selection selection,
        Data data,
        List<Extrema> extrema) {

    public static final String FORMAT = "diffract-taylor-terms";
    public static final int FORMAT_VERSION = 1;

    /**
     * @param source         the file the patch came from (informative only)
     * @param sha256         {@link diffract.optics.patches.HeightField#contentSha256()} of the mean-subtracted field
     * @param maxHeightUm    grey 255 / 65535 height the user gave (images), or null
     * @param maxAbsHeightUm max |h| after mean subtraction
     */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record Patch(String source, String sha256, int rows, int cols, double pixelSizeXUm, double pixelSizeYUm,
                        Double maxHeightUm, double maxAbsHeightUm) {
    }

    /** How N was chosen: "terms" (given) or "tolerance" (001 sec. 3.3.3 bound). */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record Selection(String mode, Double tolerance, double lambdaMinNm, double maxPhase, double remainderBound) {
    }

    /** The binary file: name, byte order, size and SHA-256 for verification before use. */
    public record Data(String file, String layout, String byteOrder, long bytes, String sha256) {
    }

    /** 003 eq. 1.1's extrema of term n. */
    public record Extrema(int n, double reMin, double reMax, double imMin, double imMax) {
    }
}
