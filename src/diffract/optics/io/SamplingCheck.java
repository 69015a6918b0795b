package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.util.Reporter;
import diffract.util.UserInputException;

import java.util.Optional;

/**
 * Checks that a height field is sampled finely enough for the wavelengths it will be rendered at.
 *
 * <p>The DFT of a field with pixel size dH holds spatial frequencies up to 1 / (2 dH) (Nyquist). The BRDF looks
 * up the frequency |u| / lambda, where u = -(omega_i + omega_r) projected onto the surface plane:
 * |u| &lt;= sin theta_i + sin theta_r &lt;= 1 + sin theta_i, so |u| &lt;= 1 for a light at normal incidence and up
 * to 2 when light and view are both grazing. So wavelengths with lambda &lt; 2 dH ask for frequencies the field does
 * not hold and alias whatever the light (a warning), and for a light at theta_i those with
 * 2 dH &lt;= lambda &lt; 2 dH (1 + sin theta_i) alias only towards the rim of the BRDF map, the grazing views (a
 * note). With the light anywhere (theta_i up to 90 degrees) that is 2 dH &lt;= lambda &lt; 4 dH.
 */
public final class SamplingCheck {
    private SamplingCheck() {
    }

    /** A closed wavelength interval [fromNm, toNm]. */
    public record WavelengthRangeNm(double fromNm, double toNm) {
    }

    /**
     * The wavelengths that alias along each axis: {@code normal*} for every light, already at normal incidence
     * (dH &gt; lambda / 2), {@code grazingOnly*} only towards grazing views
     * (lambda / (2 (1 + sin theta_i)) &lt; dH &lt;= lambda / 2). Empty where none do.
     */
    public record Result(Optional<WavelengthRangeNm> normalX, Optional<WavelengthRangeNm> normalY,
                         Optional<WavelengthRangeNm> grazingOnlyX, Optional<WavelengthRangeNm> grazingOnlyY) {
        /** True when some wavelength aliases at normal incidence along some axis. */
        public boolean aliasesAtNormalIncidence() {
            return normalX.isPresent() || normalY.isPresent();
        }
    }

    /**
     * As {@link #warnAboutAliasing(HeightField, double, double, double, Reporter)} for a light anywhere (theta_i up
     * to 90 degrees, |u| up to 2): the note covers 2 dH &lt;= lambda &lt; 4 dH.
     */
    public static Result warnAboutAliasing(HeightField field, double lambdaMinNm, double lambdaMaxNm,
                                           Reporter reporter) {
        return warnAboutAliasing(field, lambdaMinNm, lambdaMaxNm, 90, reporter);
    }

    /**
     * Warns (one message per offending axis, merged when both pixel sizes are equal) when the pixel size is
     * coarser than lambda / 2 for some lambda in [lambdaMinNm, lambdaMaxNm], and adds a milder note via
     * {@link Reporter#info} for the wavelengths that alias only towards grazing views of a light at theta_i up to
     * {@code maxThetaIDeg} (none at 0: a caller that knows no light passes 0 and hears only what aliases always).
     *
     * @throws UserInputException when the wavelength range is not 0 &lt; lambdaMinNm &lt;= lambdaMaxNm
     */
    public static Result warnAboutAliasing(HeightField field, double lambdaMinNm, double lambdaMaxNm,
                                           double maxThetaIDeg, Reporter reporter) {
        if (!(lambdaMinNm > 0) || !(lambdaMaxNm >= lambdaMinNm) || !Double.isFinite(lambdaMaxNm)) {
            throw new UserInputException("the wavelength range must satisfy 0 < min <= max (in nm), got "
                    + lambdaMinNm + " to " + lambdaMaxNm);
        }
        double reach = 1 + Math.sin(Math.toRadians(Math.max(0, Math.min(90, maxThetaIDeg)))); // the largest |u|
        double pixelXNm = field.pixelSizeXUm() * 1000.0;
        double pixelYNm = field.pixelSizeYUm() * 1000.0;
        Optional<WavelengthRangeNm> normalX = below(2 * pixelXNm, lambdaMinNm, lambdaMaxNm);
        Optional<WavelengthRangeNm> normalY = below(2 * pixelYNm, lambdaMinNm, lambdaMaxNm);
        Optional<WavelengthRangeNm> grazingX = between(2 * pixelXNm, 2 * reach * pixelXNm, lambdaMinNm, lambdaMaxNm);
        Optional<WavelengthRangeNm> grazingY = between(2 * pixelYNm, 2 * reach * pixelYNm, lambdaMinNm, lambdaMaxNm);

        // a .gsf stores extents, not pixel sizes: equal pixels come back equal to rounding only
        boolean square = Math.abs(field.pixelSizeXUm() / field.pixelSizeYUm() - 1) < 1e-6;
        report(square ? "x and y" : "x", field.pixelSizeXUm(), normalX, grazingX, lambdaMinNm, reach, maxThetaIDeg,
                reporter);
        if (!square) {
            report("y", field.pixelSizeYUm(), normalY, grazingY, lambdaMinNm, reach, maxThetaIDeg, reporter);
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
                               Optional<WavelengthRangeNm> grazingOnly, double lambdaMinNm, double reach,
                               double maxThetaIDeg, Reporter reporter) {
        String pixel = "pixel size " + ReaderSupport.num(pixelUm) + " um along " + axis;
        normal.ifPresent(range -> reporter.warn(pixel + " is coarser than lambda/2 for " + range(range)
                + " nm: those wavelengths alias at normal incidence; resample to <= "
                + ReaderSupport.num(lambdaMinNm / 2 / 1000.0) + " um"));
        String light = maxThetaIDeg >= 90 ? "when light and view are both near grazing"
                : "towards the rim of the map (views near grazing) with the light at " + ReaderSupport.num(maxThetaIDeg)
                + " degrees";
        grazingOnly.ifPresent(range -> reporter.info(pixel + " is coarser than lambda/" + ReaderSupport.num(2 * reach)
                + " for " + range(range) + " nm: those wavelengths alias only " + light + "; <= "
                + ReaderSupport.num(lambdaMinNm / (2 * reach) / 1000.0) + " um avoids it"));
    }

    private static String range(WavelengthRangeNm range) {
        return range.fromNm() == range.toNm() ? ReaderSupport.num(range.fromNm())
                : ReaderSupport.num(range.fromNm()) + "-" + ReaderSupport.num(range.toNm());
    }
}
