package diffract.app;

import diffract.optics.HeightField;
import diffract.optics.Levelling;
import diffract.optics.PatchCatalogue;
import diffract.optics.ProceduralPatches;
import diffract.optics.io.HeightFieldReader;
import diffract.pipeline.NamedPatch;
import diffract.scene.Scene;
import diffract.util.Reporter;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

import java.nio.file.Path;

/**
 * The options that name a height field, on every command that reads one: a file ({@code --patch} with the sizes
 * an image or text matrix lacks) or a named patch of the {@link PatchCatalogue} ({@code --synthetic}).
 */
final class PatchOptions {
    @Option(names = "--patch", paramLabel = "FILE",
            description = "Height field: PNG/BMP/TIFF (8 or 16 bit grey), text matrix (.txt/.csv, heights in um), "
                    + "Gwyddion .gsf or .gwy, or Igor .ibw (Asylum Research).")
    Path file;

    @Option(names = "--synthetic", paramLabel = "NAME", completionCandidates = OptionTypes.PatchNames.class,
            description = "A patch made by code instead of --patch: ${COMPLETION-CANDIDATES} (diffract patch --help "
                    + "says what they are); --period, --height, ... change it.")
    String synthetic;

    @Mixin ProceduralOptions parameters;

    @Option(names = "--max-height", paramLabel = "UM",
            description = "Height of the brightest grey value in micrometres (images; rescales text/.gsf if given).")
    Double maxHeightUm;

    @Option(names = "--pixel-size", paramLabel = "UM",
            description = "Pixel size dH in micrometres (images and text; overrides a .gsf's XReal/XRes).")
    Double pixelSizeUm;

    @Option(names = "--channel", paramLabel = "NAME|INDEX",
            description = "The channel of a .gwy or .ibw --patch, by title or index (default: the first in a length "
                    + "unit; diffract channels FILE lists them).")
    String channel;

    @Option(names = "--level", paramLabel = "L", completionCandidates = OptionTypes.LevellingNames.class,
            converter = OptionTypes.LevellingNames.Converter.class,
            description = "Levelling of a --patch before use: plane (the least-squares plane; the default for .gwy "
                    + "and .ibw, which hold the scan as measured), rows (each scan line's mean) or none (the default "
                    + "for images, text and .gsf, exported level).")
    Levelling level;

    boolean given() {
        return file != null || synthetic != null;
    }

    /** Checks what needs no file: one source at most, a known name, sizes only with a file. */
    void validate() {
        if (file != null && synthetic != null) {
            throw new diffract.util.UserInputException("give --patch FILE or --synthetic NAME, not both");
        }
        if (synthetic == null && parameters.given()) {
            throw new diffract.util.UserInputException("--period, --height, --periods, --samples-per-period, --rows, "
                    + "--seed and --size-px change a patch made by code: add --synthetic NAME");
        }
        if (synthetic != null) {
            parameters.spec(PatchCatalogue.named(synthetic));
            if (maxHeightUm != null || pixelSizeUm != null) {
                throw new diffract.util.UserInputException("--max-height and --pixel-size size a --patch FILE; "
                        + "a --synthetic patch has its own");
            }
            if (channel != null || level != null) {
                throw new diffract.util.UserInputException("--channel and --level read a --patch FILE; a --synthetic "
                        + "patch is made level");
            }
        } else if (file == null && (channel != null || level != null)) {
            throw new diffract.util.UserInputException("--channel and --level read a --patch FILE: add --patch");
        }
    }

    /** Like {@link #validate}, and one source is required. */
    void validateRequired() {
        validate();
        if (!given()) {
            throw new diffract.util.UserInputException("give the height field: --patch FILE or --synthetic NAME");
        }
    }

    /** The height field, mean-subtracted, with its name ({@code fallback} when none was given). */
    NamedPatch load(String fallback, Reporter reporter) {
        if (file != null) {
            HeightField field = HeightFieldReader.load(file, maxHeightUm, pixelSizeUm, channel, levelling(), reporter);
            return new NamedPatch(file.getFileName().toString(), field.meanSubtracted(), maxHeightUm);
        }
        PatchCatalogue.Entry entry = PatchCatalogue.named(synthetic != null ? synthetic : fallback);
        ProceduralPatches.Spec spec = parameters.spec(entry);
        return NamedPatch.of(spec.equals(entry.spec()) ? entry.name() : entry.name() + "(" + spec.periodUm() + " um)",
                spec.build());
    }

    /** As a scene's patch ({@code fallback} when none was given). */
    Scene.PatchSpec spec(String fallback) {
        if (file != null) {
            return new Scene.FilePatch(file, maxHeightUm, pixelSizeUm, channel, levelling());
        }
        PatchCatalogue.Entry entry = PatchCatalogue.named(synthetic != null ? synthetic : fallback);
        return new Scene.ProceduralPatch(entry.name(), parameters.spec(entry));
    }

    /** The levelling asked for, or null: the file format's default ({@link Levelling#defaultFor}). */
    private Levelling levelling() {
        return level;
    }

    /** The light azimuth in the plane of the patch's period: the catalogue's for a named patch, else 0. */
    double periodAzimuthDeg(String fallback) {
        return file != null ? 0 : PatchCatalogue.named(synthetic != null ? synthetic : fallback).phiIDeg();
    }
}
