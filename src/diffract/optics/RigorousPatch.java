package diffract.optics;

import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.rigorous.CellRelief;
import diffract.optics.rigorous.Profile;
import diffract.optics.rigorous.Resolution;

import java.util.Locale;
import java.util.Optional;

/**
 * A patch as the rigorous method reads it: one period of a periodic surface, as the DFT already reads it. A patch
 * whose every row (or every column) is the same is a 1-D grating: its profile across the grooves, the polyline through
 * its samples, and, where that profile repeats itself within the patch, one repeat of it (a patch of P whole periods
 * is solved on one period with 1/P the harmonics; its orders fall on every P-th texel). Any other patch is a 2-D cell:
 * its whole extent is one period in x and in y, each sample a rectangle of the cell ({@link CellRelief}).
 *
 * <p>The orders map onto the texels of the scalar model: order m of a period along x leaves at
 * omega_r.x = -omega_i.x + m lambda / period (the grating equation), where texel c's lobe sits at
 * -omega_i.x - lambda c / L (docs/design/theory.md): texel c = -m P. A 2-D cell's order (p, q) leaves at
 * (-omega_i.x + p lambda / L_x, -omega_i.y + q lambda / L_y): texel (-p, -q).
 */
public final class RigorousPatch {
    /** Relative difference (of the depth) up to which two rows, columns or repeats count as the same. */
    static final double SAME = 1e-9;

    /** Along which axis of the patch a 1-D patch's heights vary. */
    public enum Axis {
        /** Heights vary along x (the columns); the grooves run along y. */
        X,
        /** Heights vary along y (the rows); the grooves run along x. */
        Y
    }

    private final HeightField field;
    private final Axis axis;
    private final Profile profile;
    private final int repeats;

    private RigorousPatch(HeightField field, Axis axis, Profile profile, int repeats) {
        this.field = field;
        this.axis = axis;
        this.profile = profile;
        this.repeats = repeats;
    }

    /** The patch read as a grating: 1-D where its rows or columns are all the same, else a 2-D cell. */
    public static RigorousPatch of(HeightField field) {
        double depth = field.maxHeightUm() - field.minHeightUm();
        double tolerance = SAME * Math.max(depth, 1e-12);
        int rows = field.rows();
        int cols = field.cols();
        if (rows == 1 || allRowsEqual(field, tolerance)) {
            double[] line = new double[cols];
            for (int c = 0; c < cols; c++) {
                line[c] = field.heightUm(0, c);
            }
            return oneDimensional(field, Axis.X, line, field.widthUm(), tolerance);
        }
        if (cols == 1 || allColumnsEqual(field, tolerance)) {
            double[] line = new double[rows];
            for (int r = 0; r < rows; r++) {
                line[r] = field.heightUm(r, 0);
            }
            return oneDimensional(field, Axis.Y, line, field.heightExtentUm(), tolerance);
        }
        return new RigorousPatch(field, null, null, 1);
    }

    private static RigorousPatch oneDimensional(HeightField field, Axis axis, double[] line, double extentUm,
                                                double tolerance) {
        int n = line.length;
        int period = n;
        for (int d = 1; d < n; d++) {
            if (n % d == 0 && repeatsEvery(line, d, tolerance)) {
                period = d;
                break;
            }
        }
        int repeats = n / period;
        // a flat line repeats every sample: its one period is a flat polyline of two
        double[] one = period >= 2 ? java.util.Arrays.copyOf(line, period) : new double[] {line[0], line[0]};
        double periodUm = extentUm / repeats;
        String description = String.format(Locale.ROOT, "%s profile of %d samples%s, period %.4g um", axis == Axis.X
                ? "x" : "y", period, repeats > 1 ? " (repeated " + repeats + " times in the patch)" : "", periodUm);
        return new RigorousPatch(field, axis, Profile.sampled(periodUm, one, description), repeats);
    }

    private static boolean repeatsEvery(double[] line, int d, double tolerance) {
        for (int i = d; i < line.length; i++) {
            if (Math.abs(line[i] - line[i - d]) > tolerance) {
                return false;
            }
        }
        return true;
    }

    private static boolean allRowsEqual(HeightField field, double tolerance) {
        for (int r = 1; r < field.rows(); r++) {
            for (int c = 0; c < field.cols(); c++) {
                if (Math.abs(field.heightUm(r, c) - field.heightUm(0, c)) > tolerance) {
                    return false;
                }
            }
        }
        return true;
    }

    private static boolean allColumnsEqual(HeightField field, double tolerance) {
        for (int r = 0; r < field.rows(); r++) {
            for (int c = 1; c < field.cols(); c++) {
                if (Math.abs(field.heightUm(r, c) - field.heightUm(r, 0)) > tolerance) {
                    return false;
                }
            }
        }
        return true;
    }

    /** Whether it is a 1-D grating (else a 2-D cell). */
    public boolean oneDimensional() {
        return axis != null;
    }

    /** The axis along which a 1-D patch's heights vary. */
    public Axis axis() {
        return axis;
    }

    /** One period of a 1-D patch's profile. */
    public Profile profile() {
        return profile;
    }

    /** How many periods of the profile the patch holds. */
    int repeats() {
        return repeats;
    }

    HeightField field() {
        return field;
    }

    /** The texel (cx, cy) of a 1-D patch's order m. */
    public int[] texel(int order) {
        int c = -order * repeats;
        return axis == Axis.X ? new int[] {c, 0} : new int[] {0, c};
    }

    /** The texel of order (p, q): a 1-D patch's order p (q is 0), a 2-D cell's (-p, -q). */
    public int[] texel(int p, int q) {
        return oneDimensional() ? texel(p) : new int[] {-p, -q};
    }

    /** The order (p, q) of texel (cx, cy), or empty where none lands (a 1-D patch's orders have q = 0). */
    Optional<int[]> orders(int cx, int cy) {
        if (!oneDimensional()) {
            return Optional.of(new int[] {-cx, -cy});
        }
        return order(cx, cy).map(m -> new int[] {m, 0});
    }

    /** A 2-D cell's heights: the patch's samples over its whole extent. */
    CellRelief relief() {
        return new CellRelief(field.widthUm(), field.heightExtentUm(), field.cols(), field.rows(), field.heightsUm());
    }

    /** The order of texel (cx, cy), or empty where no order of a 1-D patch lands. */
    Optional<Integer> order(int cx, int cy) {
        int along = axis == Axis.X ? cx : cy;
        int across = axis == Axis.X ? cy : cx;
        if (across != 0 || along % repeats != 0) {
            return Optional.empty();
        }
        return Optional.of(-along / repeats);
    }

    /**
     * The incident wave's direction cosines in the grating's frame (alpha across the grooves, beta along them) for
     * light from omega_i (pointing away from the surface): the wave travels along -omega_i.
     */
    public double[] incidence(Direction wi) {
        return axis != Axis.Y ? new double[] {-wi.x(), -wi.y()} : new double[] {-wi.y(), -wi.x()};
    }

    /** The shortest wavelength a 2-D cell's cost is estimated at (the visible band's start) without settings. */
    static final double ESTIMATE_LAMBDA_UM = 0.38;

    /**
     * The most complex unknowns 2N = 2 (2 M_x + 1)(2 M_y + 1) one slab's eigenproblem of a 2-D cell may have
     * (M_x = M_y = 6). Measured on 2 cores (beside another job) for a pillar's slab: the eigen decomposition takes
     * 1.2 s at 2N = 242, 2.0 s at 338 (a whole one-slab solve 3.9 s), 5.8 s at 450, and at 578 Hipparchus' Schur
     * iteration no longer converges. Each wavelength node solves every distinct slab of the staircase (a cell of few
     * heights has few), at L and L / 2 layers.
     */
    static final long MAX_UNKNOWNS = 338;

    /**
     * Why the rigorous method cannot solve this patch with the default resolution from {@link #ESTIMATE_LAMBDA_UM}
     * (what a caller without settings, the viewer's A/B, asks), or empty where it can.
     */
    Optional<String> refusal() {
        return refusal(Resolution.DEFAULT, ESTIMATE_LAMBDA_UM);
    }

    /**
     * Why the rigorous method cannot solve this patch at {@code resolution} from {@code fromUm} (the band's start,
     * its widest harmonic set), or empty where it can: a 1-D grating always, a 2-D cell where its eigenproblem keeps
     * at most {@link #MAX_UNKNOWNS} complex unknowns. A larger cell is refused with the cost its solution would have,
     * estimated before any work ({@link #twoDimensionalCost}), and the ways out.
     */
    Optional<String> refusal(Resolution resolution, double fromUm) {
        if (oneDimensional()) {
            return Optional.empty();
        }
        Cost cost = twoDimensionalCost(field.widthUm(), field.heightExtentUm(), resolution, fromUm);
        if (cost.unknowns() <= MAX_UNKNOWNS) {
            return Optional.empty();
        }
        return Optional.of(String.format(Locale.ROOT, "the rigorous method solves 1-D patches (every row, or every "
                + "column, the same) and 2-D cells of up to %d complex unknowns per layer (2 (2 M + 1)^2 with the "
                + "highest harmonic M = %d), and this is %s: at %.0f nm it would keep %d x %d harmonics, an "
                + "eigenproblem of %d complex unknowns per layer (%s per matrix, about %.1g operations), for each of "
                + "%d layers, every wavelength and direction; the ways out: fewer harmonics (a lower highest "
                + "harmonic), a smaller cell (resample or crop the patch), the snake patches' ridges alone, which are "
                + "1-D (the named patches elaphe-ridge and xenopeltis-ridge), or their average ridge (the orders "
                + "command, the lobes method's rigorous orders)",
                MAX_UNKNOWNS, largestSquareOrder(), describe(), fromUm * 1e3, cost.harmonicsX(), cost.harmonicsY(),
                cost.unknowns(), diffract.util.MemoryEstimate.size((long) cost.matrixBytes()), cost.operations(),
                resolution.layers()));
    }

    /** The largest M whose square set of harmonics stays within {@link #MAX_UNKNOWNS}. */
    static int largestSquareOrder() {
        int m = 0;
        while (2L * (2 * m + 3) * (2 * m + 3) <= MAX_UNKNOWNS) {
            m++;
        }
        return m;
    }

    /**
     * What one staircase layer of a 2-D cell of {@code widthUm} x {@code heightUm} would cost the Fourier modal
     * method at {@link #ESTIMATE_LAMBDA_UM}, at the default resolution.
     */
    static Cost twoDimensionalCost(double widthUm, double heightUm) {
        return twoDimensionalCost(widthUm, heightUm, Resolution.DEFAULT, ESTIMATE_LAMBDA_UM);
    }

    /**
     * What one staircase layer of a 2-D cell costs at {@code resolution} and {@code lambdaUm}: the harmonics
     * {@link Resolution#maxOrder} keeps along each side, N = (2 M_x + 1)(2 M_y + 1), give one eigenproblem of 2N
     * complex unknowns (E_x and E_y of every harmonic), solved as its real twin of 4N (as {@code ComplexEigen} does):
     * 16 (2N)^2 bytes per complex matrix and about 10 (4N)^3 floating-point operations for the real QR algorithm.
     */
    static Cost twoDimensionalCost(double widthUm, double heightUm, Resolution resolution, double lambdaUm) {
        int nx = 2 * resolution.maxOrder(widthUm, lambdaUm) + 1;
        int ny = 2 * resolution.maxOrder(heightUm, lambdaUm) + 1;
        long unknowns = 2L * nx * ny;
        double real = 2.0 * unknowns;
        return new Cost(nx, ny, unknowns, 16.0 * unknowns * unknowns, 10 * real * real * real);
    }

    /** One layer's eigenproblem: harmonics along x and y, complex unknowns, bytes per matrix, operations. */
    record Cost(int harmonicsX, int harmonicsY, long unknowns, double matrixBytes, double operations) {
    }

    /** "a 1-D grating: x profile of 25 samples (repeated 26 times in the patch), period 2.5 um" or "a 2-D cell". */
    public String describe() {
        return oneDimensional() ? "a 1-D grating: " + profile.description()
                : String.format(Locale.ROOT, "a 2-D cell of %d x %d samples, %.4g x %.4g um", field.cols(),
                        field.rows(), field.widthUm(), field.heightExtentUm());
    }
}
