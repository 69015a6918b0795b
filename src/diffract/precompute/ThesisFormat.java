package diffract.precompute;

import diffract.optics.spectra.TaylorTerms;
import diffract.util.Reporter;
import diffract.util.UserInputException;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * The thesis' Octave precompute format, so that data precomputed by the original script renders
 * unchanged and our terms can feed the original shader. A folder holds
 * <ul>
 *   <li>{@code AmpReIm<n>.txt}, n = 0..N (binary despite the name): big-endian int32 width W (columns), int32
 *   height H (rows), then W x H x 3 big-endian float32: texel rows from the bottom row of the script's image to
 *   the top, columns left to right, the triple (Re normalised, Im normalised, 0.5);</li>
 *   <li>{@code extrema.txt}: 8 lines per term, see {@link ThesisExtrema} (eq. 1.1, pixel size dH in metres);</li>
 *   <li>{@code paramters.txt} (sic), informative, when present (see {@link ThesisWriter#parameters});</li>
 *   <li>{@code diffract.json}, only in folders diffract wrote: {@link ThesisExtras}.</li>
 * </ul>
 * The script's image is not our layout: it rotated the field by -90 degrees before the transform and the result
 * by +90 degrees after it, which moves rows by one for even heights and multiplies by a phase ramp
 * ({@link ThesisLayout}). The writer reproduces that; the reader undoes it, so {@code read(write(t))} equals
 * {@code t} texel for texel, up to the rounding of the normalisation.
 *
 * <p>Heights: term n scales as (height unit)^n. diffract writes micrometres (the extrema of term n are in
 * um^n, like the script's newer outputs); older outputs of the script used metres. The images are the same either
 * way, only the extrema differ. The reader takes micrometres when diffract.json is present; otherwise it takes
 * the unit asked for, or detects it from the RMS height that term 1 carries (Parseval: the sum of |term 1|^2 is
 * mean(h^2)): at most 2e-6 means metres, at least 2e-4 micrometres, anything between is refused with a request for
 * the unit. It says in one line which unit it assumed.
 */
public final class ThesisFormat {
    public static final String EXTREMA_FILE = "extrema.txt";
    /** The script's spelling. */
    public static final String PARAMETERS_FILE = "paramters.txt";
    public static final String EXTRAS_FILE = "diffract.json";

    private ThesisFormat() {
    }

    /** The unit of the heights the terms were computed from. */
    public enum HeightUnit {
        /** Detect from term 1 (or take micrometres when diffract.json says so). */
        AUTO,
        METRES,
        MICROMETRES;

        /** "auto", "m" or "um" (also "metres", "micrometres"). */
        public static HeightUnit parse(String text) {
            switch (text.toLowerCase(Locale.ROOT)) {
                case "auto":
                    return AUTO;
                case "m":
                case "metres":
                case "meters":
                    return METRES;
                case "um":
                case "micrometres":
                case "micrometers":
                case "microns":
                    return MICROMETRES;
                default:
                    throw new UserInputException("unknown height unit '" + text + "': use auto, m or um");
            }
        }

        String words() {
            return this == METRES ? "metres" : "micrometres";
        }

        String symbol() {
            return this == METRES ? "m" : "um";
        }
    }

    /**
     * What the files record about where the terms came from.
     *
     * @param source      the input path (last line of paramters.txt)
     * @param patchSha256 the mean-subtracted field's content hash, or null
     * @param maxHeightUm the user's --max-height, or null
     */
    public record Provenance(String source, String patchSha256, Double maxHeightUm) {
    }

    /** {@code AmpReIm<n>.txt}. */
    public static String termFileName(int n) {
        return "AmpReIm" + n + ".txt";
    }

    /** True when {@code dir} has the thesis format's extrema.txt or first term file. */
    public static boolean isThesisFolder(Path dir) {
        return Files.isRegularFile(dir.resolve(EXTREMA_FILE)) || Files.isRegularFile(dir.resolve(termFileName(0)));
    }

    /**
     * Writes {@code terms} into {@code dir} (created if needed) in the thesis layout, extrema in micrometres, plus
     * paramters.txt and diffract.json. Every file goes to a temporary name first and is renamed into place;
     * extrema.txt comes last, so a folder that has it is complete. Stale {@code AmpReIm<k>.txt} with k > N are
     * removed.
     */
    public static void write(Path dir, TaylorTerms terms, Provenance provenance, Reporter reporter) throws IOException {
        ThesisWriter.write(dir, terms, provenance, reporter);
    }

    /**
     * Reads a thesis folder into our layout and micrometre scale: the same texels and values as our own
     * precompute of the same patch. Errors (a missing or truncated term file, terms of different sizes, a bad
     * extrema.txt, an undecidable unit) are one-line {@link UserInputException}s naming the file.
     *
     * @param unit     the heights' unit, or {@link HeightUnit#AUTO}
     * @param reporter receives the one line saying which unit was assumed, and the max|h| estimate
     */
    public static TaylorTerms read(Path dir, HeightUnit unit, Reporter reporter) {
        return ThesisReader.read(dir, unit, reporter);
    }
}
