package diffract.bench;

import diffract.optics.maps.AutoExposure;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.Direction;
import diffract.optics.illumination.GainFactor;
import diffract.optics.settings.GainModel;
import diffract.optics.patches.HeightField;
import diffract.optics.Methods;
import diffract.optics.validity.OrderComparison;
import diffract.optics.settings.PixelFilter;
import diffract.optics.patches.ProceduralPatches;
import diffract.optics.rigorous.RigorousSettings;
import diffract.optics.Variant;
import diffract.optics.rigorous.Resolution;
import diffract.colour.Xyz;
import diffract.util.Reporter;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Where Stam's scalar model holds: 1-D reliefs of three shapes over their period, depth and the light's angle, each
 * drawn by the scalar model (its default gain, Rayleigh-Rice's, and Stam's) and by the rigorous method, compared in
 * colour (mean CIEDE2000 over the lit pixels of a BRDF map) and in the orders' efficiencies (the largest relative
 * error on the orders that carry at least 5 % of the reflected power at 450, 550 and 650 nm). docs/measurements/validity.md holds
 * the map; {@code assets/validity/scalar-validity.csv} the table the commands' warnings read
 * ({@link diffract.optics.validity.ScalarValidity}).
 *
 * <p>The maps: a point light in the plane of the period (phi_i = 0), the row of an S x S map (S odd) through the
 * orders (all of a 1-D grating's orders lie on it), each pixel its box's average, the wavelength integral exact; the
 * rigorous orders at {@link #STEP_NM} nm nodes, the staircase of {@link #LAYERS} slabs extrapolated from half as
 * many. Both maps are shown at the rigorous map's automatic exposure.
 */
public final class ValidityMap {
    /** The reliefs' shapes. */
    public enum Family {
        /** h = d (1 + sin 2 pi t) / 2: also the Xenopeltis-like ridge, sin^2(pi t). */
        SINUSOID(ProceduralPatches.Kind.SINUSOID),
        /** The blazed test grating's sawtooth, rising over the period. */
        SAWTOOTH(ProceduralPatches.Kind.BLAZED),
        /** The Elaphe-like patch's asymmetric ridge. */
        ELAPHE_RIDGE(ProceduralPatches.Kind.ELAPHE_RIDGE);

        private final ProceduralPatches.Kind kind;

        Family(ProceduralPatches.Kind kind) {
            this.kind = kind;
        }

        public String label() {
            return name().toLowerCase(Locale.ROOT).replace('_', '-');
        }

        public static Family parse(String label) {
            for (Family f : values()) {
                if (f.label().equals(label)) {
                    return f;
                }
            }
            throw new IllegalArgumentException("unknown relief " + label);
        }

        /** One period of this relief, {@link #SAMPLES} samples in one row: its period along x. */
        HeightField field(double periodUm, double depthUm) {
            HeightField made = new ProceduralPatches.Spec(kind, periodUm, depthUm, 1, SAMPLES, 1, 128, 0, 1L).build();
            // the ridges' catalogue patch repeats along y: its one column is the same samples as a row
            return HeightField.of(1, SAMPLES, made.heightsUm(), periodUm / SAMPLES).meanSubtracted();
        }
    }

    public static final List<Double> PERIODS_UM = List.of(0.5, 0.65, 0.8, 1.0, 1.144, 1.5, 2.5, 4.0);
    public static final List<Double> DEPTHS_UM = List.of(0.025, 0.05, 0.1, 0.2, 0.3);
    public static final List<Double> THETAS_DEG = List.of(0.0, 30.0, 60.0);
    /** Samples per period of the reliefs. */
    static final int SAMPLES = 64;
    /** The rigorous orders' wavelength nodes. */
    static final double STEP_NM = 20;
    static final int LAYERS = 16;
    /** The map's side: odd, so that a row runs through y = 0. */
    static final int SIZE_PX = 127;
    /** Orders carrying at least this share of the reflected power count in the orders' errors. */
    static final double ORDER_SHARE = 0.05;
    static final double[] ORDER_LAMBDAS_NM = {450, 550, 650};

    /** One relief at one light. */
    public record Case(Family family, double periodUm, double depthUm, double thetaDeg) {
        public String label() {
            return String.format(Locale.ROOT, "%s %.3g um / %.3g um, %.0f deg", family.label(), periodUm, depthUm,
                    thetaDeg);
        }
    }

    /**
     * What the scalar model misses on one case.
     *
     * @param deltaE          mean CIEDE2000 over the lit pixels, the default gain (Rayleigh-Rice's) against rigorous
     * @param deltaEP95       its 95th percentile
     * @param deltaEStam      the same for Stam's gain
     * @param orderError      the largest relative error of the default gain on the orders carrying 5 % of the light
     * @param orderErrorStam  the same for Stam's gain
     * @param litPixels       the lit pixels of the row
     */
    public record Result(Case c, double deltaE, double deltaEP95, double deltaEStam, double orderError,
                         double orderErrorStam, int litPixels) {
    }

    private ValidityMap() {
    }

    /** Every case of the grid, the cheap ones (short periods) first. */
    public static List<Case> grid() {
        List<Case> out = new ArrayList<>();
        for (double period : PERIODS_UM) {
            for (Family family : Family.values()) {
                for (double depth : DEPTHS_UM) {
                    for (double theta : THETAS_DEG) {
                        out.add(new Case(family, period, depth, theta));
                    }
                }
            }
        }
        return out;
    }

    /** The settings a case is drawn with: a point light, box pixels, the given gain. */
    static BrdfSettings settings(Variant variant, GainModel gain) {
        return BrdfSettings.thesis(variant).with(b -> b.pixelFilter(PixelFilter.BOX).gain(gain).lambdaStepNm(STEP_NM)
                .rigorous(RigorousSettings.DEFAULT.withResolution(new Resolution(0, LAYERS, true))));
    }

    /** Measures one case. */
    public static Result measure(Case c, Reporter reporter) {
        HeightField field = c.family().field(c.periodUm(), c.depthUm());
        Direction wi = Direction.fromSphericalDeg(c.thetaDeg(), 0);
        float[] rigorous = row(DiffractionBrdf.create(settings(Methods.Role.MAXWELL.method(), GainModel.RAYLEIGH_RICE), field,
                null), wi, reporter);
        float[] rayleighRice = row(scalar(field, GainModel.RAYLEIGH_RICE), wi, reporter);
        float[] stam = row(scalar(field, GainModel.STAM), wi, reporter);
        float[] luminance = new float[SIZE_PX * SIZE_PX];
        for (int p = 0; p < luminance.length; p++) {
            luminance[p] = rigorous[3 * p + 1];
        }
        double exposure = AutoExposure.of(luminance, SIZE_PX, -wi.x(), -wi.y());
        BrdfMapDifference rr = BrdfMapDifference.of(rayleighRice, rigorous, SIZE_PX, exposure);
        BrdfMapDifference st = BrdfMapDifference.of(stam, rigorous, SIZE_PX, exposure);
        double[] orders = orderErrors(field, wi);
        return new Result(c, mean(rr), rr.lit() == null ? 0 : rr.lit().p95(), mean(st), orders[0], orders[1],
                rr.litPixels());
    }

    private static double mean(BrdfMapDifference d) {
        return d.lit() == null ? 0 : d.lit().mean();
    }

    private static DiffractionBrdf scalar(HeightField field, GainModel gain) {
        return DiffractionBrdf.create(settings(Methods.Role.EXACT.method(), gain), field, null);
    }

    /** The S x S map, black but for its middle row (y = 0), where every order of the grating lies. */
    private static float[] row(DiffractionBrdf brdf, Direction wi, Reporter reporter) {
        float[] map = new float[3 * SIZE_PX * SIZE_PX];
        brdf.prepare(wi, reporter);
        int row = SIZE_PX / 2;
        java.util.stream.IntStream.range(0, SIZE_PX).parallel().forEach(column -> {
            Xyz c = brdf.mapPixel(wi, column, row, SIZE_PX);
            int p = 3 * (row * SIZE_PX + column);
            map[p] = (float) c.x();
            map[p + 1] = (float) c.y();
            map[p + 2] = (float) c.z();
        });
        return map;
    }

    /** The largest relative error of each gain on the orders carrying {@link #ORDER_SHARE} of the reflected light. */
    private static double[] orderErrors(HeightField field, Direction wi) {
        double rr = 0;
        double st = 0;
        BrdfSettings settings = settings(Methods.Role.MAXWELL.method(), GainModel.RAYLEIGH_RICE);
        double n = settings.illumination().refractiveIndex();
        for (double lambdaNm : ORDER_LAMBDAS_NM) {
            OrderComparison a = OrderComparison.of(field, settings, wi, lambdaNm);
            for (OrderComparison.Order o : a.orders()) {
                if (o.rigorous() < ORDER_SHARE * a.reflected()) {
                    continue;
                }
                rr = largerMagnitude(rr, o.relativeError());
                // Stam's scalar efficiency differs from Rayleigh-Rice's by the ratio of the gains alone
                Direction wr = Direction.fromProjected(o.x(), o.y());
                double stamScalar = o.scalar() * GainFactor.gainTimesShadowing(wi, wr, n, GainModel.STAM)
                        / GainFactor.gainTimesShadowing(wi, wr, n, GainModel.RAYLEIGH_RICE);
                st = largerMagnitude(st, (stamScalar - o.rigorous()) / o.rigorous());
            }
        }
        return new double[] {rr, st};
    }

    private static double largerMagnitude(double a, double b) {
        return Math.abs(b) > Math.abs(a) ? b : a;
    }
}
