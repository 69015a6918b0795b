package diffract.app.jobs;

import com.fasterxml.jackson.annotation.JsonInclude;

import java.util.List;
import java.util.Map;

/**
 * What one piece of a split run is, as {@code piece-I-of-N.json} beside its floats: which command computed it, which
 * run of the result's items it holds (rows of a BRDF map, frames of a turntable, configurations of a bench sweep),
 * everything that changes its floats ({@code inputSha256}, {@code settings}), everything that changes the files written
 * from them ({@code picture}), and the SHA-256 of its floats. A map's or a turntable's holds no time or path of the
 * run, so computing such a piece again writes the same bytes; a bench piece holds what it measured ({@code bench}:
 * GPU times, which differ from run to run) and no floats.
 *
 * @param format        {@link #FORMAT}: what the file is
 * @param command       the command that computed it and that merge writes the result as: brdfmap or render
 * @param piece         I, the piece's index
 * @param pieces        N, how many pieces the result is split into
 * @param from          the piece's first item ({@link diffract.optics.MapBand#of}: N runs as even as items allow)
 * @param to            one past its last item
 * @param items         the result's items: a map's rows, a turntable's frames
 * @param floatsPerItem floats per item: S x channels per map row, W x H x 3 per frame
 * @param inputSha256   the content hash of what the command reads (the height field)
 * @param settings      the effective settings that change the floats, as text
 * @param picture       the settings that change the files written from the floats
 * @param arguments     the options the command was run with, less --tile and --pieces: merge reads the result's
 *                      settings back from them
 * @param floatsFile    the piece's floats: little-endian float32, items in order, each item's floats in order
 * @param floatsSha256  their SHA-256
 * @param bench         a bench piece's measured rows ({@link BenchPiece}); absent from the pieces of floats
 */
public record PieceManifest(String format, String command, int piece, int pieces, int from, int to, int items,
                     int floatsPerItem, String inputSha256, Map<String, String> settings, Map<String, String> picture,
                     List<String> arguments, String floatsFile, String floatsSha256,
                     @JsonInclude(JsonInclude.Include.NON_NULL) BenchPiece bench) {
    public static final String FORMAT = "diffract piece 2";

    /** The piece as merge names it: I/N. */
    public String label() {
        return piece + "/" + pieces;
    }

    /** What pieces of one result share: a piece whose key differs was computed for another result. */
    List<Object> resultKey() {
        return List.of(command, pieces, items, floatsPerItem, inputSha256, settings, picture);
    }

    /** This manifest with its floats' file and hash filled in. */
    PieceManifest withFloats(String file, String sha256) {
        return new PieceManifest(format, command, piece, pieces, from, to, items, floatsPerItem, inputSha256, settings,
                picture, arguments, file, sha256, bench);
    }

    /** A setting that merge needs back as a number (a brdfmap piece's patch extent, its azimuth). */
    public double number(String key) {
        String value = settings.get(key);
        if (value == null) {
            throw new diffract.util.UserInputException("merge: the pieces' manifests lack '" + key + "': compute them "
                    + "again with this diffract");
        }
        return Double.parseDouble(value);
    }
}
