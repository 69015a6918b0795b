package diffract.optics;

import diffract.optics.patches.Direction;
import diffract.optics.lobes.LobeWeights;
import diffract.optics.rigorous.CellEfficiencies;
import diffract.optics.rigorous.CellSolver;
import diffract.optics.rigorous.ComplexIndex;
import diffract.optics.rigorous.OrderEfficiencies;
import diffract.optics.rigorous.RigorousSettings;
import diffract.optics.rigorous.RigorousSolver;
import diffract.optics.settings.SpectralSettings;
import diffract.util.DiskCache;
import diffract.util.Reporter;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.IntStream;

/**
 * The reflected orders' efficiencies of a patch for light from one direction, solved from Maxwell's equations
 * ({@link RigorousSolver}) at wavelength nodes over the band, and the lobe weights the filtered drawing takes from
 * them ({@link LobeWeights}): the rigorous method's map is
 * <pre>
 *   rho(omega_r) = cos theta_i / R_0 * sum_m eta_m(lambda, omega_i) exp(-|(x, y) - (x_m, y_m)|^2 / (lambda sigma_f)^2)
 * </pre>
 * integrated over the pixel, the light and the wavelengths as the reference integrates its lobes
 * ({@link FilteredReference}). Each order's lobe has unit integral over the projected solid angle divided by
 * pi (lambda sigma_f)^2, so the lobe carries eta_m of the light (docs/design/rigorous.md; the design note's
 * f = sum eta_pq K_lambda); cos theta_i / R_0 puts it on the relative BRDF's scale, where a flat mirror at normal
 * incidence (eta_0 = R_0) peaks at 1. The scalar model's lobes carry C S |T_m|^2 in its place.
 *
 * <p>Between the nodes eta_m is interpolated linearly: it is smooth in lambda except where an order appears at
 * grazing (a Rayleigh anomaly), where it has a square-root kink that the interpolation rounds over one node step.
 * The efficiencies are those at the light's centre: over a disc light the lobes move with each direction, their
 * weights do not (as the reference keeps its gain at the light's centre per disc direction, {@link DiscLightAverage}).
 *
 * <p>A 1-D patch's orders m are held as (p, q) = (m, 0); a 2-D cell's orders (p, q) come from {@link CellSolver}, each
 * on texel (-p, -q) ({@link RigorousPatch#texel(int, int)}).
 *
 * <p>Immutable and thread-safe. Tables are kept in the disk cache by the patch's content, the material, the
 * resolution, the band and the direction.
 */
final class RigorousOrders implements LobeWeights {
    /** The disk cache's folder of these tables. */
    static final String KIND = "rigorous-orders";
    private static final int FORMAT = 2;

    private final RigorousPatch patch;
    private final double firstNm;
    private final double stepNm;
    private final int nodes;
    /** The highest orders held along x and y (M_y = 0 for a 1-D patch). */
    private final int maxX;
    private final int maxY;
    /** eta[node][slot(p, q)], for the settings' polarisation. */
    private final double[][] eta;
    private final double inverseR0;
    private final double extentXUm;
    private final double extentYUm;

    private RigorousOrders(RigorousPatch patch, double firstNm, double stepNm, int maxX, int maxY, double[][] eta,
                           double inverseR0) {
        this.patch = patch;
        this.firstNm = firstNm;
        this.stepNm = stepNm;
        this.nodes = eta.length;
        this.maxX = maxX;
        this.maxY = maxY;
        this.eta = eta;
        this.inverseR0 = inverseR0;
        this.extentXUm = patch.field().widthUm();
        this.extentYUm = patch.field().heightExtentUm();
    }

    /** The wavelength nodes of a band: from its start every step, and its end. */
    static double[] nodesNm(SpectralSettings spectral) {
        double from = spectral.lambdaMinNm();
        double to = spectral.lambdaMaxNm();
        double step = spectral.lambdaStepNm();
        int count = Math.max(2, (int) Math.ceil((to - from) / step - 1e-9) + 1);
        double[] out = new double[count];
        for (int i = 0; i < count; i++) {
            out[i] = Math.min(to, from + i * step);
        }
        return out;
    }

    /**
     * The table of {@code patch} for light from {@code wi}, from the disk cache or solved (one solve per wavelength
     * node, the nodes in parallel, with progress).
     */
    static RigorousOrders of(RigorousPatch patch, BrdfSettings settings, Direction wi, DiskCache cache,
                             Reporter reporter) {
        RigorousSettings rigorous = settings.rigorous();
        ComplexIndex material = settings.illumination().material();
        double[] lambdasNm = nodesNm(settings.spectral());
        DiskCache.Key key = key(patch, settings, wi);
        double inverseR0 = 1 / material.normalReflectance();
        RigorousOrders cached = cache.load(key, in -> read(in, patch, lambdasNm, inverseR0), reporter,
                "solving the orders again");
        if (cached != null) {
            return cached;
        }
        double[] alphaBeta = patch.incidence(wi);
        int[] widest = patch.oneDimensional()
                ? new int[] {rigorous.resolution().maxOrder(patch.profile().periodUm(), lambdasNm[0] * 1e-3), 0}
                : CellSolver.maxOrders(patch.relief(), lambdasNm[0] * 1e-3, rigorous.resolution());
        double[][] eta = new double[lambdasNm.length][(2 * widest[0] + 1) * (2 * widest[1] + 1)];
        AtomicInteger done = new AtomicInteger();
        String task = String.format(Locale.ROOT, "rigorous orders, %d wavelengths, light at %.1f degrees",
                lambdasNm.length, Math.toDegrees(Math.acos(Math.min(1, wi.z()))));
        long start = System.nanoTime();
        IntStream.range(0, lambdasNm.length).parallel().forEach(j -> {
            if (patch.oneDimensional()) {
                OrderEfficiencies e = RigorousSolver.solve(patch.profile(), material, lambdasNm[j] * 1e-3,
                        alphaBeta[0], alphaBeta[1], rigorous.resolution());
                for (int i = 0; i < e.count(); i++) {
                    int order = e.order(i);
                    if (Math.abs(order) <= widest[0]) {
                        eta[j][order + widest[0]] = rigorous.polarisation().of(e.reflectedS()[i], e.reflectedP()[i]);
                    }
                }
            } else {
                CellEfficiencies e = CellSolver.solve(patch.relief(), material, lambdasNm[j] * 1e-3, alphaBeta[0],
                        alphaBeta[1], rigorous.resolution());
                for (int i = 0; i < e.count(); i++) {
                    int p = e.orderX(i);
                    int q = e.orderY(i);
                    if (Math.abs(p) <= widest[0] && Math.abs(q) <= widest[1]) {
                        eta[j][slot(p, q, widest[0], widest[1])] = rigorous.polarisation().of(e.reflectedS()[i],
                                e.reflectedP()[i]);
                    }
                }
            }
            reporter.progress(task, done.incrementAndGet() / (double) lambdasNm.length);
        });
        RigorousOrders orders = new RigorousOrders(patch, lambdasNm[0], settings.spectral().lambdaStepNm(),
                widest[0], widest[1], eta, inverseR0);
        String where = cache.store(key, out -> orders.write(out), "the rigorous orders", reporter)
                .map(f -> "cached").orElse("not cached");
        reporter.info(String.format(Locale.ROOT, "rigorous orders of %s: %d wavelengths in %.1f s (%s, %s)",
                patch.describe(), lambdasNm.length, (System.nanoTime() - start) * 1e-9,
                rigorous.resolution().describe(), where));
        return orders;
    }

    private static DiskCache.Key key(RigorousPatch patch, BrdfSettings settings, Direction wi) {
        return new DiskCache.Key(KIND, String.join("; ", "rigorous orders format " + FORMAT,
                "patch sha256 " + patch.field().contentSha256(), "material " + settings.illumination().material(),
                "rigorous " + settings.rigorous().resolution() + " " + settings.rigorous().polarisation(),
                "spectral " + settings.spectral(),
                "incidence " + wi.x() + " " + wi.y() + " " + wi.z()));
    }

    private void write(DataOutputStream out) throws IOException {
        out.writeInt(nodes);
        out.writeInt(maxX);
        out.writeInt(maxY);
        for (double[] row : eta) {
            for (double v : row) {
                out.writeDouble(v);
            }
        }
    }

    private static RigorousOrders read(DataInputStream in, RigorousPatch patch, double[] lambdasNm, double inverseR0)
            throws IOException {
        int nodes = in.readInt();
        int maxX = in.readInt();
        int maxY = in.readInt();
        if (nodes != lambdasNm.length || maxX < 0 || maxY < 0 || maxX > 50_000 || maxY > 50_000
                || (2L * maxX + 1) * (2L * maxY + 1) > 100_000) {
            throw new IOException("it holds " + nodes + " wavelengths of orders up to " + maxX + ", " + maxY
                    + ", not the band's " + lambdasNm.length);
        }
        int orders = (2 * maxX + 1) * (2 * maxY + 1);
        double[][] eta = new double[nodes][orders];
        for (double[] row : eta) {
            for (int i = 0; i < orders; i++) {
                row[i] = in.readDouble();
            }
        }
        double step = lambdasNm.length > 1 ? lambdasNm[1] - lambdasNm[0] : 1;
        return new RigorousOrders(patch, lambdasNm[0], step, maxX, maxY, eta, inverseR0);
    }

    /** The index of order (p, q) in a table of orders up to (maxX, maxY): p fastest. */
    private static int slot(int p, int q, int maxX, int maxY) {
        return (q + maxY) * (2 * maxX + 1) + p + maxX;
    }

    /** The index of order (p, q), or -1 where it is not held. */
    private int slot(int p, int q) {
        return Math.abs(p) > maxX || Math.abs(q) > maxY ? -1 : slot(p, q, maxX, maxY);
    }

    /** A 1-D patch's eta_m at {@code lambdaNm}, interpolated linearly between the nodes; 0 outside the band. */
    double efficiency(int order, double lambdaNm) {
        return efficiency(order, 0, lambdaNm);
    }

    /** eta_pq at {@code lambdaNm}, interpolated linearly between the nodes; 0 outside the band. */
    double efficiency(int p, int q, double lambdaNm) {
        int i = slot(p, q);
        if (i < 0) {
            return 0;
        }
        double t = (lambdaNm - firstNm) / stepNm;
        if (t < -1e-9 || t > nodes - 1 + 1e-9) {
            return 0;
        }
        int j = Math.min(nodes - 2, Math.max(0, (int) Math.floor(t)));
        double f = Math.min(1, Math.max(0, t - j));
        return eta[j][i] + f * (eta[j + 1][i] - eta[j][i]);
    }

    /** The node wavelengths, nm. */
    double nodeNm(int j) {
        return firstNm + j * stepNm;
    }

    int nodeCount() {
        return nodes;
    }

    /** The relative BRDF at one wavelength, point-sampled: cos theta_i / R_0 sum_m eta_m lobe_m. */
    double relative(Direction wi, Direction wr, double lambdaNm, double sigmaFPerUm) {
        double gain = gain(wi, wr);
        if (gain == 0) {
            return 0;
        }
        double lambdaUm = lambdaNm * 1e-3;
        double u = -wi.x() - wr.x();
        double v = -wi.y() - wr.y();
        double width2 = lambdaUm * sigmaFPerUm * lambdaUm * sigmaFPerUm;
        double sum = 0;
        for (int i = 0; i < eta[0].length; i++) {
            int p = i % (2 * maxX + 1) - maxX;
            int q = i / (2 * maxX + 1) - maxY;
            int[] texel = patch.texel(p, q);
            double du = u - lambdaUm * texel[0] / extentXUm;
            double dv = v - lambdaUm * texel[1] / extentYUm;
            double d2 = (du * du + dv * dv) / width2;
            if (d2 < 60) {
                sum += efficiency(p, q, lambdaNm) * Math.exp(-d2);
            }
        }
        return gain * sum;
    }

    @Override
    public boolean hasPairs() {
        return false;
    }

    @Override
    public Lobe lobe(int twiceCx, int twiceCy) {
        if (twiceCx % 2 != 0 || twiceCy % 2 != 0) {
            return null;
        }
        java.util.Optional<int[]> order = patch.orders(twiceCx / 2, twiceCy / 2);
        if (order.isEmpty() || slot(order.get()[0], order.get()[1]) < 0) {
            return null;
        }
        int p = order.get()[0];
        int q = order.get()[1];
        return new Lobe() {
            @Override
            public double weight(double lambdaUm, double w) {
                return efficiency(p, q, lambdaUm * 1e3);
            }

            @Override
            public void weightWithDerivative(double lambdaUm, double w, double[] out) {
                out[0] = efficiency(p, q, lambdaUm * 1e3);
                out[1] = 0;
            }
        };
    }

    @Override
    public double bound(int mx, int my, double fromNm, double toNm, double w, double dw) {
        java.util.Optional<int[]> order = patch.orders(mx, my);
        if (order.isEmpty()) {
            return 0;
        }
        int i = slot(order.get()[0], order.get()[1]);
        if (i < 0) {
            return 0;
        }
        int from = Math.max(0, (int) Math.floor((fromNm - firstNm) / stepNm));
        int to = Math.min(nodes - 1, (int) Math.ceil((toNm - firstNm) / stepNm));
        double max = 0;
        for (int j = from; j <= to; j++) {
            max = Math.max(max, eta[j][i]);
        }
        return max;
    }

    /** The weights do not depend on w: they grow nowhere across a box. */
    @Override
    public double slope(double kHi, double dw) {
        return 1;
    }

    /** cos theta_i / R_0 above both horizons. */
    @Override
    public double gain(Direction wi, Direction wr) {
        return wi.z() > 0 && wr.z() > 0 ? wi.z() * inverseR0 : 0;
    }

    /** The sum of the reflected efficiencies at node j: the patch's reflectance there. */
    double reflectance(int node) {
        double sum = 0;
        for (double v : eta[node]) {
            sum += v;
        }
        return sum;
    }
}
