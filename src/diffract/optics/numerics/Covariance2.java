package diffract.optics.numerics;

/**
 * A symmetric positive semi-definite 2 x 2 covariance [[xx, xy], [xy, yy]] of a Gaussian in the (u, v) plane: the
 * spread a pixel footprint, an extended light or a lobe adds to a direction.
 */
public record Covariance2(double xx, double xy, double yy) {
    public static final Covariance2 ZERO = new Covariance2(0, 0, 0);

    public Covariance2 {
        if (!(xx >= 0) || !(yy >= 0) || !Double.isFinite(xy) || xy * xy > xx * yy * (1 + 1e-9) + 1e-300) {
            throw new IllegalArgumentException("not a covariance: [[" + xx + ", " + xy + "], [" + xy + ", " + yy + "]]");
        }
    }

    /** sigma^2 I. */
    public static Covariance2 isotropic(double variance) {
        return new Covariance2(variance, 0, variance);
    }

    /** variance times d d^T for a unit direction d. */
    public static Covariance2 along(double dx, double dy, double variance) {
        return new Covariance2(variance * dx * dx, variance * dx * dy, variance * dy * dy);
    }

    /** The covariance of the sum of two independent shifts. */
    public Covariance2 plus(Covariance2 o) {
        return new Covariance2(xx + o.xx, xy + o.xy, yy + o.yy);
    }

    public Covariance2 scaled(double factor) {
        return new Covariance2(xx * factor, xy * factor, yy * factor);
    }

    public double determinant() {
        return xx * yy - xy * xy;
    }

    /**
     * Whether the off-diagonal entry is negligible (below 1e-9 of the geometric mean of the variances: a light
     * whose azimuth lies on an axis, up to rounding of sin and cos).
     */
    public boolean isDiagonal() {
        return Math.abs(xy) <= 1e-9 * Math.sqrt(xx * yy);
    }

    public boolean isZero() {
        return xx == 0 && yy == 0;
    }

    /**
     * This covariance as a diagonal part plus a rank-one part along a unit direction, both positive semi-definite:
     * with b = xy and k = sqrt(xx / yy), the rank-one part is v v^T, v = (sqrt(|b| k), sign(b) sqrt(|b| / k)), which
     * leaves xx - |b| k = sqrt(xx) (sqrt(xx) - |b| / sqrt(yy)) &gt;= 0 (and the same for yy) because b^2 &lt;= xx yy.
     * A box of the (u, v) plane averages the diagonal part analytically (erf per axis) and the rank-one part by a
     * one-dimensional integral along its direction.
     *
     * @return {diagonal xx, diagonal yy, direction x, direction y, variance along the direction}
     */
    public double[] diagonalPlusRankOne() {
        if (isDiagonal()) {
            return new double[] {xx, yy, 1, 0, 0};
        }
        double b = Math.abs(xy);
        double k = Math.sqrt(xx / yy);
        double px = Math.sqrt(b * k);
        double py = Math.copySign(Math.sqrt(b / k), xy);
        double variance = px * px + py * py;
        double length = Math.sqrt(variance);
        return new double[] {Math.max(0, xx - px * px), Math.max(0, yy - py * py), px / length, py / length, variance};
    }
}
