package diffract.app;

import diffract.optics.HeightField;
import diffract.optics.io.HeightFieldReader;
import diffract.util.Reporter;
import picocli.CommandLine.Option;

import java.nio.file.Path;

/** The options that name a height field, shared by every command that reads one. */
final class PatchInput {
    @Option(names = "--patch", required = true, paramLabel = "FILE",
            description = "Height field: PNG/BMP/TIFF (8 or 16 bit grey), text matrix (.txt/.csv, heights in um) or Gwyddion .gsf.")
    Path patch;

    @Option(names = "--max-height", paramLabel = "UM",
            description = "Height of the brightest grey value in micrometres (images; rescales text/.gsf if given).")
    Double maxHeightUm;

    @Option(names = "--pixel-size", paramLabel = "UM",
            description = "Pixel size dH in micrometres (images and text; overrides a .gsf's XReal/XRes).")
    Double pixelSizeUm;

    /** The mean-subtracted field. */
    HeightField load(Reporter reporter) {
        return HeightFieldReader.load(patch, maxHeightUm, pixelSizeUm, reporter);
    }
}
