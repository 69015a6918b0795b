package diffract.app;

import java.util.List;
import java.util.Map;

/**
 * What one piece of a split BRDF map is, as {@code piece-I-of-N.json} beside its floats: everything that changes the
 * floats ({@code settings}, the patch's content hash, the map size), everything that changes the pictures written from
 * them ({@code picture}), which band it covers, and the SHA-256 of its floats. It holds no time or path of the run, so
 * computing a piece again writes the same bytes.
 *
 * @param format        {@link #FORMAT}: what the file is
 * @param piece         I, the band's index
 * @param pieces        N, how many bands the map is split into
 * @param fromRow       the band's first row
 * @param toRow         one past its last row
 * @param sizePx        the map's size S (S x S pixels)
 * @param channels      floats per pixel: 3 (CIE XYZ) or 1 (the relative BRDF at one wavelength)
 * @param patchSha256   the height field's content hash ({@link diffract.optics.HeightField#contentSha256})
 * @param patchWidthUm  the patch's extent along x, for the black-map notice
 * @param patchHeightUm ... along y
 * @param settings      the effective settings that change the floats, as text
 * @param picture       the settings that change the PNG and OpenEXR files written from the floats
 * @param arguments     the brdfmap options it was run with, less --tile and --pieces: merge reads the picture
 *                      settings back from them
 * @param floatsFile    the piece's floats: little-endian float32, rows from the band's top, pixels left to right
 * @param floatsSha256  their SHA-256
 */
record PieceManifest(String format, int piece, int pieces, int fromRow, int toRow, int sizePx, int channels,
                     String patchSha256, double patchWidthUm, double patchHeightUm, Map<String, String> settings,
                     Map<String, String> picture, List<String> arguments, String floatsFile, String floatsSha256) {
    static final String FORMAT = "diffract brdfmap piece 1";

    /** The piece as merge names it: I/N. */
    String label() {
        return piece + "/" + pieces;
    }

    /** What pieces of one map share: a piece whose key differs was computed for another map. */
    List<Object> mapKey() {
        return List.of(pieces, sizePx, channels, patchSha256, settings, picture);
    }
}
