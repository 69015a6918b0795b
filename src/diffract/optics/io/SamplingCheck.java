package diffract.optics.io;

import diffract.optics.HeightField;
import diffract.util.Reporter;
import diffract.util.UserInputException;

import java.util.Optional;

/**
 * Checks that a height field is sampled finely enough for the wavelengths it will be rendered at.
 *
 * <p>The DFT of a field with pixel size dH holds spatial frequencies up to 1 / (2 dH) (Nyquist). The BRDF looks
 * up the frequency |u| / lambda, where u is the projection of the half-way vector onto the surface plane:
 * |u| &lt;= 1 at normal incidence and up to 2 at grazing incidence and viewing. So wavelengths with
 * lambda &lt; 2 dH ask for frequencies the field does not hold and alias even at normal incidence, and those with
 * 2 dH &lt;= lambda &lt; 4 dH alias only towards grazing angles.
 */
public final class SamplingCheck {
    private SamplingCheck() {
    }

    /** A closed wavelength interval [fromNm, toNm]. */
    public record WavelengthRangeNm(double fromNm, double toNm) {
    }

    /**
     * The wavelengths that alias along each axis: {@code normal*} at normal incidence (dH &gt; lambda / 2),
     * {@code grazingOnly*} only at grazing angles (lambda / 4 &lt; dH &lt;= lambda / 2). Empty where none do.
     */
    public record Result(Optional<WavelengthRangeNm> normalX, Optional<WavelengthRangeNm> normalY,
                         Optional<WavelengthRangeNm> grazingOnlyX, Optional<WavelengthRangeNm> grazingOnlyY) {
        /** True when some wavelength aliases at normal incidence along some axis. */
        public boolean aliasesAtNormalIncidence() {
            return normalX.isPresent() || normalY.isPresent();
        }
    }

    /**
     * Warns (one message per offending axis, merged when both pixel sizes are equal) when the pixel size is
     * coarser than lambda / 2 for some lambda in [lambdaMinNm, lambdaMaxNm], and adds a milder note via
     * {@link Reporter#info} when it is coarser than lambda / 4 (aliasing at grazing angles only).
     *
     * @throws UserInputException when the wavelength range is not 0 &lt; lambdaMinNm &lt;= lambdaMaxNm
     */
    public static Result warnAboutAliasing(HeightField field, double lambdaMinNm, double lambdaMaxNm,
                                           Reporter reporter) {
        if (!(lambdaMinNm > 0) || !(lambdaMaxNm >= lambdaMinNm) || !Double.isFinite(lambdaMaxNm)) {
            throw new UserInputException("the wavelength range must satisfy 0 < min <= max (in nm), got "
                    + lambdaMinNm + " to " + lambdaMaxNm);
        }
        double pixelXNm = field.pixelSizeXUm() * 1000.0;
        double pixelYNm = field.pixelSizeYUm() * 1000.0;
        Optional<WavelengthRangeNm> normalX = below(2 * pixelXNm, lambdaMinNm, lambdaMaxNm);
        Optional<WavelengthRangeNm> normalY = below(2 * pixelYNm, lambdaMinNm, lambdaMaxNm);
        Optional<WavelengthRangeNm> grazingX = between(2 * pixelXNm, 4 * pixelXNm, lambdaMinNm, lambdaMaxNm);
        Optional<WavelengthRangeNm> grazingY = between(2 * pixelYNm, 4 * pixelYNm, lambdaMinNm, lambdaMaxNm);

        boolean square = field.pixelSizeXUm() == field.pixelSizeYUm();
        report(square ? "x and y" : "x", field.pixelSizeXUm(), normalX, grazingX, lambdaMinNm, reporter);
        if (!square) {
            report("y", field.pixelSizeYUm(), normalY, grazingY, lambdaMinNm, reporter);
        }
        return new Result(normalX, normalY, grazingX, grazingY);
    }

    /** The wavelengths in [min, max] below the limit (lambda &lt; limit), as a closed range for display. */
    private static Optional<WavelengthRangeNm> below(double limitNm, double minNm, double maxNm) {
        if (limitNm <= minNm) {
            return Optional.empty();
        }
        return Optional.of(new WavelengthRangeNm(minNm, Math.min(maxNm, limitNm)));
    }

    /** The wavelengths in [min, max] with low &lt;= lambda &lt; high. */
    private static Optional<WavelengthRangeNm> between(double lowNm, double highNm, double minNm, double maxNm) {
        double from = Math.max(minNm, lowNm);
        double to = Math.min(maxNm, highNm);
        if (from > maxNm || highNm <= minNm || from >= highNm) {
            return Optional.empty();
        }
        return Optional.of(new WavelengthRangeNm(from, to));
    }

    private static void report(String axis, double pixelUm, Optional<WavelengthRangeNm> normal,
                               Optional<WavelengthRangeNm> grazingOnly, double lambdaMinNm, Reporter reporter) {
        String pixel = "pixel size " + ReaderSupport.num(pixelUm) + " um along " + axis;
        normal.ifPresent(range -> reporter.warn(pixel + " is coarser than lambda/2 for " + range(range)
                + " nm: those wavelengths alias at normal incidence; resample to <= "
                + ReaderSupport.num(lambdaMinNm / 2 / 1000.0) + " um"));
        grazingOnly.ifPresent(range -> reporter.info(pixel + " is coarser than lambda/4 for " + range(range)
                + " nm: those wavelengths alias at grazing angles only; <= "
                + ReaderSupport.num(lambdaMinNm / 4 / 1000.0) + " um avoids it"));
    }

    private static String range(WavelengthRangeNm range) {
        return range.fromNm() == range.toNm() ? ReaderSupport.num(range.fromNm())
                : ReaderSupport.num(range.fromNm()) + "-" + ReaderSupport.num(range.toNm());
    }
}
