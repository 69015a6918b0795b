package diffract.optics.patches;

import diffract.util.UserInputException;

import java.util.Random;

/**
 * Snake-skin and grating patches made by code from documented parameters (no measured data is copied): the
 * profiles the {@link PatchCatalogue}'s named patches and a scene file's {@code "procedural"} patches are made of.
 * The Elaphe-like patch and the gratings are {@link SyntheticPatches}; the Xenopeltis-like patch is here.
 */
public final class ProceduralPatches {
    /** Xenopeltis unicolor's ridge period: reported between 0.6 and 0.7 um; 0.65 chosen to resemble it. */
    public static final double XENOPELTIS_RIDGE_PERIOD_UM = 0.65;
    /** Ridge height: about 0.1 um, shallow compared with Elaphe's 0.3 um. */
    public static final double XENOPELTIS_RIDGE_HEIGHT_UM = 0.1;

    private ProceduralPatches() {
    }

    /**
     * The profiles. The blazed and sinusoidal gratings have grooves along the rows (their period along x); the snake
     * patches and their ridges' cross-sections have ridges along the columns (their period along y).
     */
    public enum Kind {
        BLAZED, SINUSOID, ELAPHE_LIKE, XENOPELTIS_LIKE, ELAPHE_SCAN, ELAPHE_RIDGE, XENOPELTIS_RIDGE;

        /**
         * 1-D gratings: sized by samples per period and by {@code rows}, the samples along the grooves (the rows of
         * the blazed and sinusoidal gratings, the columns of the ridges); the snake patches by a square size in
         * pixels.
         */
        public boolean isGrating() {
            return this == BLAZED || this == SINUSOID || this == ELAPHE_RIDGE || this == XENOPELTIS_RIDGE;
        }
    }

    /**
     * A procedural patch: a profile and its parameters (the scene-file keys of the same names).
     *
     * @param kind             the profile
     * @param periodUm         ridge or groove period
     * @param heightUm         peak-to-valley height of the profile
     * @param periods          whole periods across the patch
     * @param samplesPerPeriod pixels per period (gratings); the snake patches use {@code sizePx / periods}
     * @param rows             rows of a grating (its grooves are constant along them)
     * @param sizePx           pixels per side of a snake patch (a multiple of 16)
     * @param roughnessUm      standard deviation of the per-pixel noise before smoothing (Xenopeltis-like)
     * @param seed             random seed of the snake patches' noise and phases
     */
    public record Spec(Kind kind, double periodUm, double heightUm, int periods, int samplesPerPeriod, int rows,
                       int sizePx, double roughnessUm, long seed) {
        public Spec {
            java.util.Objects.requireNonNull(kind, "kind");
        }

        /** The height field; the same spec gives the same field. */
        public HeightField build() {
            switch (kind) {
                case XENOPELTIS_LIKE:
                    return xenopeltisLike(sizePx, periods, periodUm, heightUm, roughnessUm, seed);
                case BLAZED:
                    return SyntheticPatches.blazed(periodUm, heightUm, samplesPerPeriod, periods, rows);
                case SINUSOID:
                    return SyntheticPatches.sinusoid(periodUm, heightUm, samplesPerPeriod, periods, rows);
                case ELAPHE_SCAN:
                    return SyntheticPatches.elapheScan(sizePx, periods, periodUm, heightUm, seed);
                case ELAPHE_RIDGE:
                    return SyntheticPatches.ridges(SyntheticPatches::fingerProfile, periodUm, heightUm,
                            samplesPerPeriod, periods, rows);
                case XENOPELTIS_RIDGE:
                    return SyntheticPatches.ridges(ProceduralPatches::xenopeltisProfile, periodUm, heightUm,
                            samplesPerPeriod, periods, rows);
                default:
                    return SyntheticPatches.elapheLike(sizePx, periods, periodUm, heightUm, seed);
            }
        }

        public Spec withSeed(long s) {
            return new Spec(kind, periodUm, heightUm, periods, samplesPerPeriod, rows, sizePx, roughnessUm, s);
        }
    }

    /**
     * A procedural stand-in for the dorsal scales of Xenopeltis unicolor (the sunbeam snake), chosen to resemble
     * what is reported of them: very regular, shallow, smooth ridges, period 0.6 to 0.7 um and height about 0.1 um,
     * which make the strong rainbow iridescence of the species. Ridges run along x (columns) and repeat along y
     * (rows), as in {@link SyntheticPatches#elapheLike}, so the same scene orientation serves both.
     *
     * <ul>
     *   <li>profile across a ridge, phase t in [0, 1): sin^2(pi t), symmetric and smooth (no Elaphe "fingers");</li>
     *   <li>regularity: the ridges meander by only 2 % of a period, y + 0.02 d sin(2 pi x / width + phi);</li>
     *   <li>noise: seeded Gaussian of {@code roughnessUm} per pixel, smoothed by a 3 x 3 box with wrap-around.</li>
     * </ul>
     *
     * @param sizePx pixels per side, a multiple of 16; the pixel size is ridges * periodUm / sizePx
     */
    public static HeightField xenopeltisLike(int sizePx, int ridges, double periodUm, double heightUm,
                                             double roughnessUm, long seed) {
        if (sizePx < 16 || sizePx % 16 != 0 || ridges < 1 || !(periodUm > 0) || !(heightUm >= 0)
                || !(roughnessUm >= 0)) {
            throw new UserInputException("a Xenopeltis-like patch needs a size that is a multiple of 16, >= 1 ridge, "
                    + "period > 0, height >= 0 and roughness >= 0");
        }
        Random random = new Random(seed);
        double pixelUm = ridges * periodUm / sizePx;
        double widthUm = sizePx * pixelUm;
        double wavinessPhase = 2 * Math.PI * random.nextDouble();
        double[] noise = new double[sizePx * sizePx];
        for (int i = 0; i < noise.length; i++) {
            noise[i] = roughnessUm * random.nextGaussian();
        }
        double[] h = new double[sizePx * sizePx];
        for (int r = 0; r < sizePx; r++) {
            for (int c = 0; c < sizePx; c++) {
                double x = c * pixelUm;
                double y = r * pixelUm + 0.02 * periodUm * Math.sin(2 * Math.PI * x / widthUm + wavinessPhase);
                h[r * sizePx + c] = heightUm * xenopeltisProfile(y / periodUm) + boxMean(noise, sizePx, r, c);
            }
        }
        return HeightField.of(sizePx, sizePx, h, pixelUm);
    }

    /** The Xenopeltis-like ridge across its period, t in [0, 1): sin^2(pi t), peak 1 at t = 1/2. */
    static double xenopeltisProfile(double t) {
        double s = Math.sin(Math.PI * t);
        return s * s;
    }

    private static double boxMean(double[] field, int size, int r, int c) {
        double sum = 0;
        for (int dr = -1; dr <= 1; dr++) {
            for (int dc = -1; dc <= 1; dc++) {
                sum += field[Math.floorMod(r + dr, size) * size + Math.floorMod(c + dc, size)];
            }
        }
        return sum / 9;
    }
}
