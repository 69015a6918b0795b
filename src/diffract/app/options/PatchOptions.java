package diffract.app.options;

import diffract.optics.patches.HeightField;
import diffract.optics.patches.Levelling;
import diffract.optics.patches.PatchCatalogue;
import diffract.optics.patches.ProceduralPatches;
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
public final class PatchOptions {
    @Option(names = "--patch", paramLabel = "FILE") public Path file;

    @Option(names = "--synthetic", paramLabel = "NAME", completionCandidates = OptionTypes.PatchNames.class)
    String synthetic;

    @Mixin ProceduralOptions parameters;

    @Option(names = "--max-height", paramLabel = "UM") Double maxHeightUm;

    @Option(names = "--pixel-size", paramLabel = "UM") Double pixelSizeUm;

    @Option(names = "--channel", paramLabel = "NAME|INDEX") String channel;

    @Option(names = "--level", paramLabel = "L", completionCandidates = OptionTypes.LevellingNames.class,
            converter = OptionTypes.LevellingNames.Converter.class)
    Levelling level;

    public boolean given() {
        return file != null || synthetic != null;
    }

    /** Checks what needs no file: one source at most, a known name, sizes only with a file. */
    public void validate() {
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
    public void validateRequired() {
        validate();
        if (!given()) {
            throw new diffract.util.UserInputException("give the height field: --patch FILE or --synthetic NAME");
        }
    }

    /** The height field, mean-subtracted, with its name ({@code fallback} when none was given). */
    public NamedPatch load(String fallback, Reporter reporter) {
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
    public Scene.PatchSpec spec(String fallback) {
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

    /** The options that name the patch, as a user would give them again: "--synthetic elaphe-like", "--patch F". */
    public String describe() {
        if (file != null) {
            return "--patch " + file + (maxHeightUm != null ? " --max-height " + maxHeightUm : "")
                    + (pixelSizeUm != null ? " --pixel-size " + pixelSizeUm : "") + (channel != null ? " --channel "
                    + channel : "");
        }
        return synthetic != null ? "--synthetic " + synthetic + parameters.describe() : "";
    }

    /** The light azimuth in the plane of the patch's period: the catalogue's for a named patch, else 0. */
    public double periodAzimuthDeg(String fallback) {
        return file != null ? 0 : PatchCatalogue.named(synthetic != null ? synthetic : fallback).phiIDeg();
    }
}
