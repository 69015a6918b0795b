package diffract.pipeline;

import diffract.optics.patches.HeightField;

import java.util.Objects;

/**
 * A height field with where it came from, as the term cache records it.
 *
 * @param name           a file name or a catalogue name ("elaphe-like"), for titles, logs and the cache's sidecar
 * @param meanSubtracted the heights with their mean removed
 * @param maxHeightUm    the height of white the user gave for an image, or null
 */
public record NamedPatch(String name, HeightField meanSubtracted, Double maxHeightUm) {
    public NamedPatch {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(meanSubtracted, "meanSubtracted");
        if (Math.abs(meanSubtracted.meanUm()) > 1e-9 * Math.max(1.0, meanSubtracted.maxAbsHeightUm())) {
            throw new IllegalArgumentException("the patch must be mean-subtracted (HeightField.meanSubtracted)");
        }
    }

    /** A patch made by code (no image scale). */
    public static NamedPatch of(String name, HeightField field) {
        return new NamedPatch(name, field.meanSubtracted(), null);
    }
}
