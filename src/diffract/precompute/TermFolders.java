package diffract.precompute;

import diffract.optics.spectra.TaylorTerms;
import diffract.util.Reporter;
import diffract.util.UserInputException;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Reads precomputed terms from a folder in either format, whichever it holds: diffract's own ({@link TermStore},
 * recognised by terms.json) or the thesis' Octave layout ({@link ThesisFormat}, recognised by extrema.txt or
 * AmpReIm0.txt). Everything that accepts precomputed terms goes through here.
 */
public final class TermFolders {
    private TermFolders() {
    }

    /** The two on-disk formats. */
    public enum Format {
        NATIVE,
        THESIS
    }

    /** The format of {@code dir}; a folder with neither format's files is a one-line error. */
    public static Format detect(Path dir) {
        if (!Files.isDirectory(dir)) {
            throw new UserInputException("no folder " + dir + " (precomputed terms are a folder: ./diffract "
                    + "precompute ... -o DIR)");
        }
        if (Files.isRegularFile(dir.resolve(TermStore.SIDECAR_FILE))) {
            return Format.NATIVE;
        }
        if (ThesisFormat.isThesisFolder(dir)) {
            return Format.THESIS;
        }
        throw new UserInputException(dir + " holds no precomputed terms: neither " + TermStore.SIDECAR_FILE
                + " (diffract's format) nor " + ThesisFormat.EXTREMA_FILE + " and " + ThesisFormat.termFileName(0)
                + " (the thesis' Octave format)");
    }

    /**
     * The terms of {@code dir} in our layout and micrometre scale.
     *
     * @param thesisHeightUnit used only for a thesis folder without diffract.json
     */
    public static TaylorTerms read(Path dir, ThesisFormat.HeightUnit thesisHeightUnit, Reporter reporter) {
        if (detect(dir) == Format.THESIS) {
            return ThesisFormat.read(dir, thesisHeightUnit, reporter);
        }
        try {
            return TermStore.read(dir);
        } catch (TermStore.Damaged e) {
            TermSidecar sidecar = null;
            try {
                sidecar = TermStore.readSidecar(dir);
            } catch (TermStore.Damaged unreadable) {
                // the hint then names no patch
            }
            throw new UserInputException(e.getMessage() + "; " + TermStore.repairHint(dir, sidecar), e);
        }
    }

    /** As {@link #read(Path, ThesisFormat.HeightUnit, Reporter)} with the unit detected. */
    public static TaylorTerms read(Path dir, Reporter reporter) {
        return read(dir, ThesisFormat.HeightUnit.AUTO, reporter);
    }
}
