package diffract.optics.illumination;

import diffract.optics.numerics.Covariance2;

/**
 * What one pixel averages the BRDF over, in the (u, v) plane of (u, v, w) = -omega_i - omega_r, around the
 * direction the pixel is centred on: an axis-aligned box (a BRDF-map pixel) and a Gaussian (the light's spread,
 * and on a surface the pixel's own footprint), convolved.
 *
 * <p>A BRDF-map pixel of an S x S map covers a square of side 2 / S in the projected (x, y) plane of omega_r; since
 * (u, v) = -omega_i.xy - (x, y), that square is a square of the same side in (u, v) (mirrored). A surface pixel
 * covers the parallelogram spanned by the screen-space derivatives J_x = d(u, v)/dx and J_y = d(u, v)/dy; its box
 * is replaced by the Gaussian of equal covariance, (J_x J_x^T + J_y J_y^T) / 12 (the unit square's variance 1/12
 * per axis, mapped by the Jacobian).
 *
 * @param halfWidthU half the box's side along u (0: no box)
 * @param halfWidthV half the box's side along v
 * @param gaussian   the covariance of the Gaussian convolved with the box (zero: none)
 */
public record Footprint(double halfWidthU, double halfWidthV, Covariance2 gaussian) {
    public static final Footprint POINT = new Footprint(0, 0, Covariance2.ZERO);

    public Footprint {
        if (!(halfWidthU >= 0) || !(halfWidthV >= 0) || !Double.isFinite(halfWidthU) || !Double.isFinite(halfWidthV)) {
            throw new IllegalArgumentException("box half-widths must be finite and >= 0, got " + halfWidthU + ", "
                    + halfWidthV);
        }
    }

    /** A pixel of an S x S BRDF map: a square of side 2 / S. */
    public static Footprint mapPixel(int size) {
        double half = 1.0 / size;
        return new Footprint(half, half, Covariance2.ZERO);
    }

    /** A surface pixel with screen-space derivatives (du/dx, dv/dx) and (du/dy, dv/dy). */
    public static Footprint surfacePixel(double dudx, double dvdx, double dudy, double dvdy) {
        return new Footprint(0, 0, new Covariance2((dudx * dudx + dudy * dudy) / 12.0, (dudx * dvdx + dudy * dvdy) / 12.0,
                (dvdx * dvdx + dvdy * dvdy) / 12.0));
    }

    /** This footprint convolved with a further Gaussian (e.g. {@link LightSource#uvCovariance}). */
    public Footprint plus(Covariance2 extra) {
        return new Footprint(halfWidthU, halfWidthV, gaussian.plus(extra));
    }

    /** The box replaced by the Gaussian of equal variance ((2 h)^2 / 12 = h^2 / 3 per axis). */
    public Footprint boxAsGaussian() {
        return new Footprint(0, 0, gaussian.plus(new Covariance2(halfWidthU * halfWidthU / 3.0, 0,
                halfWidthV * halfWidthV / 3.0)));
    }

    public boolean hasBox() {
        return halfWidthU > 0 || halfWidthV > 0;
    }

    public boolean isPoint() {
        return !hasBox() && gaussian.isZero();
    }
}
