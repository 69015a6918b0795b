package diffract.optics.validity;

import diffract.optics.OrderCorrection;
import diffract.optics.patches.HeightField;
import diffract.optics.RigorousPatch;
import diffract.optics.settings.GainModel;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeSet;

/**
 * How far the scalar model is expected to be from Maxwell's equations on a patch: the validity map measured by
 * {@code diffract validity} (docs/measurements/validity.md), shipped as {@code assets/validity/scalar-validity.csv}, looked up at the
 * patch's period and depth and the light's angle. The commands say so in one line where the expected CIEDE2000
 * exceeds {@link #VISIBLE}.
 *
 * <p>A patch is summed up by its dominant period (the strongest texel of its height field's DFT, the DC aside; for a
 * 1-D grating its own period) and its depth (a 1-D grating's peak-to-valley; else the peak-to-valley of a sinusoid of
 * the same root-mean-square height, 2 sqrt 2 rms, since a rough patch's extremes say little). The table's CIEDE2000 is
 * interpolated in (log period, depth, angle), clamped to its range, and the worst of its reliefs' shapes is taken:
 * the shape of a measured ridge is not known.
 */
public final class ScalarValidity {
    /** The resource of the shipped table. */
    public static final String RESOURCE = "assets/validity/scalar-validity.csv";
    /** CIEDE2000 above which a difference is seen side by side. */
    public static final double VISIBLE = 1.0;

    /** The expected error and what it was looked up at. */
    public record Estimate(double deltaE, double periodUm, double depthUm, double thetaDeg, boolean outsideTable) {
        public boolean visible() {
            return deltaE > VISIBLE;
        }

        /**
         * "the scalar model is expected about CIEDE2000 6.3 from Maxwell's equations on this patch (period 1.14 um,
         * 0.3 um deep, light at 30 degrees; docs/measurements/validity.md)"; "at least" where the patch lies beyond the table.
         */
        public String describe() {
            return String.format(java.util.Locale.ROOT, "the scalar model is expected %s CIEDE2000 %.2g from Maxwell's "
                    + "equations on this patch (period %.3g um, %.2g um deep, light at %.0f degrees; docs/measurements/validity.md)",
                    outsideTable ? "at least" : "about", deltaE, periodUm, depthUm, thetaDeg);
        }
    }

    /** Per relief: CIEDE2000 of each gain at [period][depth][theta]. */
    private record Grid(double[][][] rayleighRice, double[][][] stam) {
    }

    private final double[] periodsUm;
    private final double[] logPeriodsUm;
    /** The table's depths after a depth of 0, where no relief has no error. */
    private final double[] depthsUm;
    private final double[] thetasDeg;
    private final Map<String, Grid> reliefs;

    private ScalarValidity(double[] periodsUm, double[] depthsUm, double[] thetasDeg, Map<String, Grid> reliefs) {
        this.periodsUm = periodsUm;
        this.logPeriodsUm = java.util.Arrays.stream(periodsUm).map(Math::log).toArray();
        this.depthsUm = depthsUm;
        this.thetasDeg = thetasDeg;
        this.reliefs = reliefs;
    }

    private static volatile ScalarValidity shipped;

    /** The shipped table. */
    public static ScalarValidity shipped() {
        ScalarValidity s = shipped;
        if (s == null) {
            try (InputStream in = ScalarValidity.class.getClassLoader().getResourceAsStream(RESOURCE)) {
                if (in == null) {
                    throw new IllegalStateException(RESOURCE + " is missing from the classpath");
                }
                s = parse(new String(in.readAllBytes(), StandardCharsets.UTF_8));
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
            shipped = s;
        }
        return s;
    }

    /** A table in the CSV form {@code diffract validity} writes. */
    public static ScalarValidity parse(String csv) {
        List<String[]> rows = new ArrayList<>();
        try (BufferedReader r = new BufferedReader(new java.io.StringReader(csv))) {
            for (String line = r.readLine(); line != null; line = r.readLine()) {
                if (!line.isBlank() && !line.startsWith("#") && !line.startsWith("relief,")) {
                    rows.add(line.split(","));
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        TreeSet<Double> periods = new TreeSet<>();
        TreeSet<Double> depths = new TreeSet<>();
        TreeSet<Double> thetas = new TreeSet<>();
        for (String[] f : rows) {
            periods.add(Double.parseDouble(f[1]));
            depths.add(Double.parseDouble(f[2]));
            thetas.add(Double.parseDouble(f[3]));
        }
        double[] p = periods.stream().mapToDouble(Double::doubleValue).toArray();
        depths.add(0.0); // a flat patch is a mirror, exact in every model: 0 at depth 0
        double[] d = depths.stream().mapToDouble(Double::doubleValue).toArray();
        double[] t = thetas.stream().mapToDouble(Double::doubleValue).toArray();
        Map<String, Grid> reliefs = new HashMap<>();
        for (String[] f : rows) {
            Grid g = reliefs.computeIfAbsent(f[0], k -> new Grid(zeroAtDepth0(p.length, d.length, t.length),
                    zeroAtDepth0(p.length, d.length, t.length)));
            int i = java.util.Arrays.binarySearch(p, Double.parseDouble(f[1]));
            int j = java.util.Arrays.binarySearch(d, Double.parseDouble(f[2]));
            int k = java.util.Arrays.binarySearch(t, Double.parseDouble(f[3]));
            g.rayleighRice[i][j][k] = Double.parseDouble(f[4]);
            g.stam[i][j][k] = Double.parseDouble(f[6]);
        }
        if (p.length < 2 || d.length < 3 || t.length < 2) {
            throw new IllegalArgumentException("a validity table needs at least two periods, depths and angles");
        }
        return new ScalarValidity(p, d, t, reliefs);
    }

    /** A table of NaN (cases not measured) but for its first depth, 0. */
    private static double[][][] zeroAtDepth0(int a, int b, int c) {
        double[][][] out = new double[a][b][c];
        for (double[][] x : out) {
            for (int j = 1; j < b; j++) {
                java.util.Arrays.fill(x[j], Double.NaN);
            }
        }
        return out;
    }

    /** The expected CIEDE2000 of the scalar model with {@code gain} on {@code meanSubtracted} lit at thetaDeg. */
    public Estimate estimate(HeightField meanSubtracted, double thetaDeg, GainModel gain) {
        double[] pd = periodAndDepth(meanSubtracted);
        return estimate(pd[0], pd[1], thetaDeg, gain);
    }

    /** The expected CIEDE2000 at a period, depth and angle: the worst relief shape's, interpolated. */
    public Estimate estimate(double periodUm, double depthUm, double thetaDeg, GainModel gain) {
        boolean outside = periodUm < periodsUm[0] || periodUm > periodsUm[periodsUm.length - 1]
                || depthUm > depthsUm[depthsUm.length - 1] || thetaDeg > thetasDeg[thetasDeg.length - 1];
        double worst = 0;
        for (Grid g : reliefs.values()) {
            double[][][] table = gain == GainModel.RAYLEIGH_RICE ? g.rayleighRice : g.stam;
            double v = interpolate(table, Math.log(periodUm), depthUm, thetaDeg);
            if (!Double.isNaN(v)) {
                worst = Math.max(worst, v);
            }
        }
        return new Estimate(worst, periodUm, depthUm, thetaDeg, outside);
    }

    /** Trilinear in (log period, depth, angle), clamped to the table. */
    private double interpolate(double[][][] table, double logPeriod, double depth, double theta) {
        int[] i = new int[1];
        int[] j = new int[1];
        int[] k = new int[1];
        double fi = locate(logPeriodsUm, logPeriod, i);
        double fj = locate(depthsUm, depth, j);
        double fk = locate(thetasDeg, theta, k);
        double sum = 0;
        for (int a = 0; a <= 1; a++) {
            for (int b = 0; b <= 1; b++) {
                for (int c = 0; c <= 1; c++) {
                    double w = (a == 0 ? 1 - fi : fi) * (b == 0 ? 1 - fj : fj) * (c == 0 ? 1 - fk : fk);
                    if (w > 0) {
                        sum += w * table[i[0] + a][j[0] + b][k[0] + c];
                    }
                }
            }
        }
        return sum;
    }

    /** The cell of sorted {@code axis} holding x (clamped): its index into {@code at}, the fraction returned. */
    private static double locate(double[] axis, double x, int[] at) {
        if (x <= axis[0]) {
            at[0] = 0;
            return 0;
        }
        for (int n = 0; n < axis.length - 1; n++) {
            if (x <= axis[n + 1]) {
                at[0] = n;
                return (x - axis[n]) / (axis[n + 1] - axis[n]);
            }
        }
        at[0] = axis.length - 2;
        return 1;
    }

    /** {period, depth} in um: a 1-D grating's own, else the dominant texel's period and 2 sqrt 2 rms. */
    static double[] periodAndDepth(HeightField meanSubtracted) {
        RigorousPatch patch = RigorousPatch.of(meanSubtracted);
        if (patch.oneDimensional()) {
            return new double[] {patch.profile().periodUm(), patch.profile().depthUm()};
        }
        double[] h = meanSubtracted.heightsUm();
        double sumSquares = 0;
        for (double v : h) {
            sumSquares += v * v;
        }
        int[] dominant = OrderCorrection.dominantTexel(meanSubtracted);
        double frequency = Math.hypot(dominant[0] / meanSubtracted.widthUm(),
                dominant[1] / meanSubtracted.heightExtentUm());
        double rms = Math.sqrt(sumSquares / h.length);
        double period = frequency > 0 ? 1 / frequency : Math.max(meanSubtracted.widthUm(), meanSubtracted.heightExtentUm());
        return new double[] {period, 2 * Math.sqrt(2) * rms};
    }
}
