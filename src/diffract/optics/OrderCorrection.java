package diffract.optics;

import diffract.optics.patches.Direction;
import diffract.optics.illumination.GainFactor;
import diffract.optics.illumination.IlluminationSettings;
import diffract.optics.numerics.ShiftedDft;
import diffract.optics.patches.HeightField;
import diffract.optics.rigorous.OrderEfficiencies;
import diffract.optics.rigorous.Profile;
import diffract.optics.rigorous.RigorousSolver;
import diffract.util.DiskCache;
import diffract.util.Reporter;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.IntStream;

/**
 * The rigorous orders for the fast path: per order of a patch's ridge, the ratio of its efficiency from Maxwell's
 * equations to the scalar model's, tabulated over the wavelength and the light's direction, by which the lobes method
 * multiplies each lobe's weight W_m (docs/design/rigorous.md, "The rigorous orders on the fast path"). On a 1-D patch the
 * corrected lobe carries the rigorous order exactly at the table's nodes; on a 2-D snake patch each texel takes the
 * ratio of the ridge order it belongs to, measured on the patch's average ridge.
 *
 * <p><b>The ridge.</b> A 1-D patch is its own ridge ({@link RigorousPatch}: its profile, repeated P times). A 2-D patch's
 * ridges run across its dominant spatial frequency (the strongest texel of its DFT, the DC aside): its heights averaged
 * along the ridges give a cross-section, which folded over the R ridges the patch holds along that axis gives the
 * average ridge, {@link #SAMPLES} samples of one period L / R. Texel c along the axis belongs to ridge order
 * m = round(-c / R) (texel c = -m R on a 1-D patch, {@link RigorousPatch#texel}).
 *
 * <p><b>The table.</b> Nodes: the band every {@link #STEP_NM} nm; the incident wave's direction cosines in the ridge's
 * frame, alpha across the ridges in [-1, 1] and |beta| along them in [0, 1] (efficiencies are even in beta: the
 * ridge's mirror image along itself), every {@link #ANGLE_STEP}; a node beyond the unit disk is solved at its radial
 * projection onto a circle of radius {@link #MAX_RADIUS}. At each node the rigorous solve ({@link RigorousSolver}, the
 * settings' resolution and polarisation) and the scalar efficiency of the same order on the same ridge
 * (R_0 C S |T_m(k w)|^2 / cos theta_i at the order's direction, the settings' gain model, T_m of the ridge's samples)
 * give ratio = eta_rigorous / max(eta_scalar, floor), floor = {@link #FLOOR} of the scalar reflectance (an order the
 * scalar model leaves dark stays dark), capped at {@link #MAX_RATIO}. Orders that do not propagate keep 1. Lookups are
 * trilinear in (lambda, alpha, beta).
 *
 * <p>Immutable and thread-safe; kept in the disk cache by the ridge's samples, the material, the rigorous settings,
 * the gain model and the band.
 */
public final class OrderCorrection {
    /** The disk cache's folder of these tables. */
    static final String KIND = "order-corrections";
    private static final int FORMAT = 1;
    /** Samples of the average ridge of a 2-D patch. */
    static final int SAMPLES = 64;
    /** Wavelength nodes every this many nm. */
    public static final double STEP_NM = 20;
    /** Direction nodes every this much of a direction cosine. */
    public static final double ANGLE_STEP = 0.125;
    /** Nodes beyond the unit disk are solved this far from the normal (81 degrees). */
    static final double MAX_RADIUS = 0.985;
    /** The scalar efficiency's floor in the ratio, as a fraction of the scalar model's reflectance there. */
    static final double FLOOR = 1e-3;
    /** The largest ratio kept. */
    public static final double MAX_RATIO = 50;

    private final RigorousPatch.Axis axis;
    /** Ridges across the patch along its axis (P of a 1-D patch). */
    private final int ridges;
    private final double firstNm;
    private final int nodes;
    /** The highest order held: orders -M..M. */
    private final int maxOrder;
    private final int alphas;
    private final int betas;
    /** ratio[((order + M) * betas + b) * alphas * nodes + a * nodes + j]: the GPU's 3-D texture, x = lambda. */
    private final float[] ratio;
    private final float largest;
    private final String describe;

    private OrderCorrection(RigorousPatch.Axis axis, int ridges, double firstNm, int nodes, int maxOrder, int alphas,
                            int betas, float[] ratio, String describe) {
        this.axis = axis;
        this.ridges = ridges;
        this.firstNm = firstNm;
        this.nodes = nodes;
        this.maxOrder = maxOrder;
        this.alphas = alphas;
        this.betas = betas;
        this.ratio = ratio;
        float max = 1;
        for (float r : ratio) {
            max = Math.max(max, r);
        }
        this.largest = max;
        this.describe = describe;
    }

    /** A patch's ridge: its profile, the axis across the ridges and how many ridges the patch holds along it. */
    record Ridge(Profile profile, RigorousPatch.Axis axis, int ridges, double[] samples) {
    }

    /** The ridge of a 1-D patch, or the average ridge of a 2-D one. */
    static Ridge ridgeOf(HeightField meanSubtracted) {
        RigorousPatch patch = RigorousPatch.of(meanSubtracted);
        if (patch.oneDimensional()) {
            Profile p = patch.profile();
            int n = SAMPLES;
            double[] samples = new double[n];
            for (int i = 0; i < n; i++) {
                samples[i] = p.at(i / (double) n);
            }
            return new Ridge(p, patch.axis(), patch.repeats(), samples);
        }
        int rows = meanSubtracted.rows();
        int cols = meanSubtracted.cols();
        int[] dominant = dominantTexel(meanSubtracted);
        boolean alongY = Math.abs(dominant[1]) >= Math.abs(dominant[0]);
        int ridges = Math.max(1, Math.abs(alongY ? dominant[1] : dominant[0]));
        int n = alongY ? rows : cols;
        double[] line = new double[n];
        for (int i = 0; i < n; i++) {
            double sum = 0;
            int across = alongY ? cols : rows;
            for (int k = 0; k < across; k++) {
                sum += alongY ? meanSubtracted.heightUm(i, k) : meanSubtracted.heightUm(k, i);
            }
            line[i] = sum / across;
        }
        // folded: sample t of the average ridge is the mean over the ridges of the cross-section there, interpolated
        double[] samples = new double[SAMPLES];
        for (int s = 0; s < SAMPLES; s++) {
            double sum = 0;
            for (int r = 0; r < ridges; r++) {
                double x = (r + s / (double) SAMPLES) * n / ridges;
                int i = (int) Math.floor(x);
                double f = x - i;
                sum += line[Math.floorMod(i, n)] * (1 - f) + line[Math.floorMod(i + 1, n)] * f;
            }
            samples[s] = sum / ridges;
        }
        double extent = alongY ? meanSubtracted.heightExtentUm() : meanSubtracted.widthUm();
        Profile profile = Profile.sampled(extent / ridges, samples, String.format(Locale.ROOT,
                "the average of %d ridges along %s, period %.4g um", ridges, alongY ? "y" : "x", extent / ridges));
        return new Ridge(profile, alongY ? RigorousPatch.Axis.Y : RigorousPatch.Axis.X, ridges, samples);
    }

    /** The strongest texel of the height field's DFT, the DC aside: {cx, cy}. */
    public static int[] dominantTexel(HeightField meanSubtracted) {
        int rows = meanSubtracted.rows();
        int cols = meanSubtracted.cols();
        double[] h = meanSubtracted.heightsUm();
        double[] complex = new double[2 * h.length];
        for (int i = 0; i < h.length; i++) {
            complex[2 * i] = h[i];
        }
        double[] spectrum = ShiftedDft.inverse(complex, rows, cols);
        double best = -1;
        int[] at = {0, 0};
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                int mx = c - cols / 2;
                int my = r - rows / 2;
                if (mx == 0 && my == 0) {
                    continue;
                }
                int p = 2 * (r * cols + c);
                double power = spectrum[p] * spectrum[p] + spectrum[p + 1] * spectrum[p + 1];
                if (power > best) {
                    best = power;
                    at = new int[] {mx, my};
                }
            }
        }
        return at;
    }

    /** The table of {@code meanSubtracted} for {@code settings}, from the disk cache or solved with progress. */
    public static OrderCorrection of(HeightField meanSubtracted, BrdfSettings settings, DiskCache cache,
                                     Reporter reporter) {
        Ridge ridge = ridgeOf(meanSubtracted);
        double fromNm = settings.spectral().lambdaMinNm();
        double toNm = settings.spectral().lambdaMaxNm();
        int nodes = Math.max(2, (int) Math.ceil((toNm - fromNm) / STEP_NM - 1e-9) + 1);
        int alphas = (int) Math.round(2 / ANGLE_STEP) + 1;
        int betas = (int) Math.round(1 / ANGLE_STEP) + 1;
        int maxOrder = (int) Math.floor(2 * ridge.profile().periodUm() / (fromNm * 1e-3));
        String describe = ridge.profile().description();
        DiskCache.Key key = key(ridge, settings, fromNm, toNm);
        float[] cached = cache.load(key, in -> read(in, (2 * maxOrder + 1) * betas * alphas * nodes), reporter,
                "solving the table of rigorous orders again");
        if (cached != null) {
            return new OrderCorrection(ridge.axis(), ridge.ridges(), fromNm, nodes, maxOrder, alphas, betas, cached,
                    describe);
        }
        float[] ratio = new float[(2 * maxOrder + 1) * betas * alphas * nodes];
        java.util.Arrays.fill(ratio, 1f);
        int directions = alphas * betas;
        AtomicInteger done = new AtomicInteger();
        String task = String.format(Locale.ROOT, "the rigorous orders' table of %s, %d wavelengths x %d directions",
                describe, nodes, directions);
        long start = System.nanoTime();
        double r0 = GainFactor.normalReflectance(settings.illumination().refractiveIndex());
        IntStream.range(0, nodes * directions).parallel().forEach(task2 -> {
            int j = task2 % nodes;
            int d = task2 / nodes;
            int a = d % alphas;
            int b = d / alphas;
            double lambdaNm = Math.min(toNm, fromNm + j * STEP_NM);
            double[] ab = onDisk(-1 + a * ANGLE_STEP, b * ANGLE_STEP);
            solveNode(ridge, settings, r0, lambdaNm, ab[0], ab[1], maxOrder, (m, value) -> ratio[index(m, maxOrder,
                    b, betas, a, alphas, j, nodes)] = value);
            reporter.progress(task, done.incrementAndGet() / (double) (nodes * directions));
        });
        OrderCorrection table = new OrderCorrection(ridge.axis(), ridge.ridges(), fromNm, nodes, maxOrder, alphas,
                betas, ratio, describe);
        String where = cache.store(key, out -> write(out, ratio), "the rigorous orders' table", reporter)
                .map(f -> "cached").orElse("not cached");
        reporter.info(String.format(Locale.ROOT, "the rigorous orders' table of %s: %d solves in %.0f s (%s)", describe,
                nodes * directions, (System.nanoTime() - start) * 1e-9, where));
        return table;
    }

    /** (alpha, beta), or its radial projection onto the circle of radius {@link #MAX_RADIUS} beyond it. */
    static double[] onDisk(double alpha, double beta) {
        double r = Math.hypot(alpha, beta);
        return r <= MAX_RADIUS ? new double[] {alpha, beta} : new double[] {alpha * MAX_RADIUS / r, beta * MAX_RADIUS / r};
    }

    private static int index(int m, int maxOrder, int b, int betas, int a, int alphas, int j, int nodes) {
        return (((m + maxOrder) * betas + b) * alphas + a) * nodes + j;
    }

    /** Receives one order's ratio. */
    private interface Sink {
        void put(int order, float ratio);
    }

    /** Solves one node: the ratio of each propagating order. */
    private static void solveNode(Ridge ridge, BrdfSettings settings, double r0, double lambdaNm, double alpha,
                                  double beta, int maxOrder, Sink sink) {
        IlluminationSettings illumination = settings.illumination();
        OrderEfficiencies e = RigorousSolver.solve(ridge.profile(), illumination.material(), lambdaNm * 1e-3, alpha,
                beta, settings.rigorous().resolution());
        double kappa0 = Math.sqrt(Math.max(0, 1 - alpha * alpha - beta * beta));
        Direction wi = new Direction(-alpha, -beta, kappa0); // in the ridge's frame: x across, y along
        double k = 2 * Math.PI / (lambdaNm * 1e-3);
        double[] scalar = new double[2 * maxOrder + 1];
        double total = 0;
        for (int m = -maxOrder; m <= maxOrder; m++) {
            double am = alpha + m * lambdaNm * 1e-3 / ridge.profile().periodUm();
            if (am * am + beta * beta >= 1) {
                continue;
            }
            Direction wr = Direction.fromProjected(am, beta);
            double t2 = coefficientPower(ridge.samples(), k * (-wi.z() - wr.z()), m);
            scalar[m + maxOrder] = r0 * GainFactor.gainTimesShadowing(wi, wr, illumination.refractiveIndex(),
                    illumination.gain()) * t2 / wi.z();
            total += scalar[m + maxOrder];
        }
        for (int m = -maxOrder; m <= maxOrder; m++) {
            int i = e.index(m);
            double am = alpha + m * lambdaNm * 1e-3 / ridge.profile().periodUm();
            if (i < 0 || am * am + beta * beta >= 1) {
                continue;
            }
            double rigorous = settings.rigorous().polarisation().of(e.reflectedS()[i], e.reflectedP()[i]);
            double ratio = rigorous / Math.max(scalar[m + maxOrder], FLOOR * total + 1e-30);
            sink.put(m, (float) Math.min(MAX_RATIO, ratio));
        }
    }

    /**
     * |T_m(a)|^2 of the ridge's samples: the DFT coefficient of exp(i a h) at the frequency of order m, which is
     * texel -m (docs/design/theory.md's sign: exp(i a h) = sum_c T_c exp(-2 pi i c x / L)), as the patch's own texels are.
     */
    static double coefficientPower(double[] samples, double a, int m) {
        int n = samples.length;
        double re = 0;
        double im = 0;
        for (int i = 0; i < n; i++) {
            double phase = a * samples[i] - 2 * Math.PI * m * i / (double) n;
            re += Math.cos(phase);
            im += Math.sin(phase);
        }
        return (re * re + im * im) / ((double) n * n);
    }

    private static DiskCache.Key key(Ridge ridge, BrdfSettings settings, double fromNm, double toNm) {
        return new DiskCache.Key(KIND, String.join("; ", "order corrections format " + FORMAT,
                "ridge " + ridge.profile().periodUm() + " " + java.util.Arrays.toString(ridge.samples()),
                "material " + settings.illumination().material(), "gain " + settings.illumination().gain(),
                "rigorous " + settings.rigorous().resolution() + " " + settings.rigorous().polarisation(), "band " + fromNm + ".." + toNm, "step " + STEP_NM,
                "angles " + ANGLE_STEP));
    }

    private static void write(DataOutputStream out, float[] ratio) throws IOException {
        out.writeInt(ratio.length);
        DiskCache.writeFloats(out, ratio);
    }

    private static float[] read(DataInputStream in, int expected) throws IOException {
        int n = in.readInt();
        if (n != expected) {
            throw new IOException("it holds " + n + " ratios, not " + expected);
        }
        float[] out = new float[n];
        DiskCache.readFloats(in, out);
        return out;
    }

    /** The ratio by which the lobe of texel (cx, cy) is multiplied at lambdaNm for light from wi (patch frame). */
    public double ratio(int cx, int cy, double lambdaNm, Direction wi) {
        int along = axis == RigorousPatch.Axis.X ? cx : cy;
        int m = (int) Math.round(-along / (double) ridges);
        if (m < -maxOrder || m > maxOrder) {
            return 1;
        }
        double alpha = axis == RigorousPatch.Axis.X ? -wi.x() : -wi.y();
        double beta = Math.abs(axis == RigorousPatch.Axis.X ? wi.y() : wi.x());
        double tj = clamp((lambdaNm - firstNm) / STEP_NM, nodes - 1);
        double ta = clamp((alpha + 1) / ANGLE_STEP, alphas - 1);
        double tb = clamp(beta / ANGLE_STEP, betas - 1);
        int j = Math.min(nodes - 2, (int) tj);
        int a = Math.min(alphas - 2, (int) ta);
        int b = Math.min(betas - 2, (int) tb);
        double fj = tj - j;
        double fa = ta - a;
        double fb = tb - b;
        double sum = 0;
        for (int db = 0; db <= 1; db++) {
            for (int da = 0; da <= 1; da++) {
                for (int dj = 0; dj <= 1; dj++) {
                    double w = (dj == 0 ? 1 - fj : fj) * (da == 0 ? 1 - fa : fa) * (db == 0 ? 1 - fb : fb);
                    sum += w * ratio[index(m, maxOrder, b + db, betas, a + da, alphas, j + dj, nodes)];
                }
            }
        }
        return sum;
    }

    private static double clamp(double t, double max) {
        return Math.max(0, Math.min(max, t));
    }

    /** The largest ratio of the table: the lobes method's bounds grow by it. */
    public double largest() {
        return largest;
    }

    /** What the table was made from. */
    public String describe() {
        return describe;
    }

    /** The texture's data for the GPU: x the wavelength, y alpha, z order x |beta| (see the field). */
    public float[] textureData() {
        return ratio.clone();
    }

    public int nodes() {
        return nodes;
    }

    public int alphas() {
        return alphas;
    }

    public int betas() {
        return betas;
    }

    public int maxOrder() {
        return maxOrder;
    }

    public int ridges() {
        return ridges;
    }

    /** 0 where the ridges' period lies along x, 1 along y. */
    public int axisIndex() {
        return axis == RigorousPatch.Axis.X ? 0 : 1;
    }

    public double firstNm() {
        return firstNm;
    }
}
