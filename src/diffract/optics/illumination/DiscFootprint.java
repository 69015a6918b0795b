package diffract.optics.illumination;

import diffract.optics.numerics.Covariance2;
import diffract.optics.numerics.ErrorFunction;
import diffract.optics.patches.Direction;
import diffract.optics.settings.GainModel;

/**
 * A disc light as the lobes method averages over it (docs/design/filtering.md, "The disc in the lobes method"): uniform
 * radiance over the cone of half-angle R about omega_i, seen from one pixel direction omega_r.
 *
 * <p><b>Where the disc lies in (u, v).</b> The cone's directions d project onto the (x, y) plane as the inside of the
 * projection of its rim circle (the upper hemisphere is a graph over the unit disc, so while the cone stays above the
 * horizon this is exact): an ellipse centred at cos R omega_i.xy with semi-axis a = sin R along
 * e = (-sin phi_i, cos phi_i) and b = sin R cos theta_i along r = (cos phi_i, sin phi_i), the rim's in-plane direction
 * e_theta projecting to cos theta_i r. A pixel sees d at (u, v)(d) = -d.xy - omega_r.xy: the same ellipse around
 * uv_0 + (1 - cos R) omega_i.xy, with uv_0 = -omega_i.xy - omega_r.xy the pixel's (u, v) at the light's centre. Uniform
 * over solid angle, the light's density per unit (u, v) is p = 1 / (Omega d_z), Omega = 2 pi (1 - cos R).
 *
 * <p><b>A lobe averaged over the disc.</b> A lobe of peak 1 at mu with variance sigma_uv^2 / 2 (its integral over the
 * plane pi sigma_uv^2) averages to
 * <pre>
 *     A = pi sigma_uv^2 p(d_mu) Phi(dist(mu) / s),
 * </pre>
 * dist the signed distance from mu to the ellipse's rim (positive inside), to first order in the rim's curvature,
 * (1 - rho) / |grad rho| with rho the ellipse's normalised radius, and s the blur across the rim along its normal n:
 * the lobe's sigma_uv^2 / 2 and the footprint's Gaussian; a map pixel's box is averaged over exactly, its projection
 * onto n a trapezoid ({@link BoxedEdge}). The disc's other quantities are taken at d_mu, the
 * direction that puts the lobe on the pixel's centre: d_mu.xy = -mu - omega_r.xy (brought onto the rim from outside):
 * its w = -(d_z + omega_r.z) for the lobe's weight W(k w), and its gain times shadowing C S(d_mu, omega_r), given
 * relative to the pixel's gain at the light's centre (by which the caller multiplies). So C, S and w follow the
 * disc's directions, where the Gaussian profile holds them at its centre (an error of order sigma_a).
 *
 * <p><b>Small discs.</b> The straight rim needs b well above s. Below, the uniform ellipse is replaced by the Gaussian
 * of its covariance (a^2 / 4 along e, b^2 / 4 along r: the Gaussian profile of the same diameter, measured within
 * CIEDE2000 0.11 of the disc at 2 degrees on the reference), blended smoothly for b / s between
 * {@link #GAUSSIAN_BELOW} and {@link #EDGE_ABOVE} (s there holds the box's variance h^2 / 3 too); a map pixel's box
 * is then averaged over exactly (erf per axis, {@link LobeGeometry#averagedLobe}) with the Gaussian's diagonal, as the
 * rim averages it exactly across its normal ({@link BoxedEdge}).
 *
 * <p><b>The wavelength nodes.</b> Along a lobe's passage A(lambda) has a plateau and two rims, each as wide in
 * wavelength as the lobe and the pixel's box across it over the lobe's speed; the passage's nodes follow that width
 * as a Gaussian light's do ({@code LobeSpectrum}).
 */
public final class DiscFootprint {
    /** b / s below which the disc is its Gaussian of equal covariance. */
    public static final double GAUSSIAN_BELOW = 1.0;
    /** b / s above which the disc is the uniform ellipse with a blurred straight rim. */
    public static final double EDGE_ABOVE = 3.0;

    private final double centreU;
    private final double centreV;
    private final double eU;
    private final double eV;
    private final double a;
    private final double b;
    private final double solidAngle;
    private final double cosR;
    private final Direction wi;
    private final Direction wr;
    private final double refractiveIndex;
    private final GainModel gainModel;
    private final double centreGain;

    /**
     * The disc of {@code light} about {@code wi} as the pixel at {@code wr} sees it, around the pixel's (u, v) at the
     * light's centre.
     */
    public DiscFootprint(LightSource light, Direction wi, Direction wr, double refractiveIndex, GainModel gain) {
        if (!light.isDisc()) {
            throw new IllegalArgumentException("a disc light of finite size is required, got " + light);
        }
        double r = light.halfAngleRad();
        this.cosR = Math.cos(r);
        double sinR = Math.sin(r);
        double sinTheta = Math.hypot(wi.x(), wi.y());
        double rx = sinTheta < 1e-12 ? 1 : wi.x() / sinTheta;
        double ry = sinTheta < 1e-12 ? 0 : wi.y() / sinTheta;
        this.eU = -ry;
        this.eV = rx;
        this.a = sinR;
        this.b = sinR * wi.z();
        this.centreU = -wi.x() - wr.x() + (1 - cosR) * wi.x();
        this.centreV = -wi.y() - wr.y() + (1 - cosR) * wi.y();
        this.solidAngle = 2 * Math.PI * (1 - cosR);
        this.wi = wi;
        this.wr = wr;
        this.refractiveIndex = refractiveIndex;
        this.gainModel = gain;
        this.centreGain = GainFactor.gainTimesShadowing(wi, wr, refractiveIndex, gain);
    }

    /** The ellipse's semi-axis across the plane of incidence, sin R. */
    public double semiAxisE() {
        return a;
    }

    /** The ellipse's semi-axis in the plane of incidence, sin R cos theta_i. */
    public double semiAxisR() {
        return b;
    }

    /**
     * How far the disc reaches from the pixel's (u, v) at the light's centre along u (axis 0) or v (axis 1): the
     * ellipse's support plus its centre's offset.
     */
    public double reach(int axis) {
        double e = axis == 0 ? eU : eV;
        double rr = axis == 0 ? eV : -eU; // r = (e.v, -e.u)
        double offset = (1 - cosR) * (axis == 0 ? wi.x() : wi.y());
        return Math.abs(offset) + Math.sqrt(a * a * e * e + b * b * rr * rr);
    }

    /**
     * Whether any lobe sees a rim: b at least {@link #GAUSSIAN_BELOW} times the narrowest blur's standard deviation
     * (its variance given); otherwise the disc is its Gaussian ({@link #covariance}) for every lobe.
     */
    public boolean hasRims(double narrowestBlurVariance) {
        return b > GAUSSIAN_BELOW * Math.sqrt(narrowestBlurVariance);
    }

    /** Directions per ring that {@link #gainBound} samples, on the rim and on the ring at half its radius. */
    public static final int RING_SAMPLES = 8;

    /**
     * A bound on the gain relative to the centre's ({@link #average}'s factor) over the disc, for the lobes method's
     * cutoff: the largest of the ratios at the centre (1) and at {@link #RING_SAMPLES} directions on each of two rings
     * (the rim and half its radius, offset by half a step), plus half the range of all those samples, the most the
     * ratio can rise between samples where it changes no faster than across them; 1 where the centre's gain is 0
     * (every direction's share is then 0).
     */
    public double gainBound() {
        if (centreGain <= 0) {
            return 1;
        }
        double rU = eV;
        double rV = -eU;
        double largest = 1;
        double smallest = 1;
        for (int ring = 1; ring <= 2; ring++) {
            double scale = 1.0 / ring;
            for (int k = 0; k < RING_SAMPLES; k++) {
                double beta = 2 * Math.PI * (k + 0.5 * (ring - 1)) / RING_SAMPLES;
                double onU = scale * (a * Math.cos(beta) * eU + b * Math.sin(beta) * rU);
                double onV = scale * (a * Math.cos(beta) * eV + b * Math.sin(beta) * rV);
                double dx = -(centreU + onU) - wr.x();
                double dy = -(centreV + onV) - wr.y();
                double ratio = gainRatio(dx, dy, 1 - dx * dx - dy * dy);
                largest = Math.max(largest, ratio);
                smallest = Math.min(smallest, ratio);
            }
        }
        return largest + 0.5 * (largest - smallest);
    }

    /** The disc's Gaussian of equal covariance in (u, v): a^2 / 4 along e, b^2 / 4 along r. */
    public Covariance2 covariance() {
        return Covariance2.along(eU, eV, a * a / 4).plus(Covariance2.along(eV, -eU, b * b / 4));
    }

    /** The largest density per unit (u, v), 1 / (Omega d_z) at the disc's lowest direction. */
    public double peakDensity() {
        double lowest = Math.cos(Math.min(Math.PI / 2 - 1e-3, Math.acos(Math.min(1, wi.z())) + Math.acos(cosR)));
        return 1 / (solidAngle * lowest);
    }

    /**
     * The lobe of spread sigmaUv at (muU, muV) averaged over the disc, as seen by a footprint of Gaussian g and box
     * half-widths (hx, hy) centred on the pixel: {average relative to the centre's gain, w at d_mu} into {@code out}.
     *
     * @param fast the shader's erfc ({@link ErrorFunction#fastErfc}) instead of the accurate one
     */
    public void average(double sigmaUv, double muU, double muV, double hx, double hy, Covariance2 g, boolean fast,
                        double[] out) {
        double lobeVariance = 0.5 * sigmaUv * sigmaUv;
        double qu = muU - centreU;
        double qv = muV - centreV;
        double xe = qu * eU + qv * eV;
        double xr = qu * eV - qv * eU;
        double rho = Math.sqrt(square(xe / a) + square(xr / b));
        // the rim's outward normal in (u, v) and the distance to it (first order in its curvature)
        double ge = xe / (a * a);
        double gr = xr / (b * b);
        double gNorm = Math.hypot(ge, gr);
        double nu;
        double nv;
        double dist;
        if (rho < 1e-12 || gNorm < 1e-300) {
            nu = eV;
            nv = -eU;
            dist = b;
        } else {
            nu = (ge * eU + gr * eV) / gNorm;
            nv = (ge * eV - gr * eU) / gNorm;
            dist = (1 - rho) * rho / gNorm;
        }
        double gaussianVariance = lobeVariance + g.xx() * nu * nu + 2 * g.xy() * nu * nv + g.yy() * nv * nv;
        double blurVariance = gaussianVariance + (hx * hx * nu * nu + hy * hy * nv * nv) / 3;
        double s = Math.sqrt(blurVariance);
        double edgeWeight = smoothstep(GAUSSIAN_BELOW, EDGE_ABOVE, b / s);
        // a blurred curved rim holds less inside than a straight one: the rim moved in by s^2 kappa / 2 (kappa its
        // curvature at the nearest point, cos t = x_e / (a rho), sin t = x_r / (b rho)) keeps the disc's integral
        // to first order in s kappa (the straight rim's excess, s^2 / 2 per unit curvature, integrates to pi s^2)
        double cosT = rho < 1e-12 ? 0 : xe / (a * rho);
        double sinT = rho < 1e-12 ? 1 : xr / (b * rho);
        double kappa = a * b / Math.pow(a * a * sinT * sinT + b * b * cosT * cosT, 1.5);
        dist -= 0.5 * blurVariance * kappa;
        // the direction that puts the lobe on the pixel's centre, brought onto the rim from outside
        double t = rho > 1 ? 1 / rho : 1;
        double dx = -(centreU + t * qu) - wr.x();
        double dy = -(centreV + t * qv) - wr.y();
        double dz2 = 1 - dx * dx - dy * dy;
        double dz = Math.sqrt(Math.max(1e-12, dz2));
        double gain = gainRatio(dx, dy, dz2);
        double value = 0;
        if (edgeWeight > 0) {
            double density = 1 / (solidAngle * dz);
            // the rim blurred by the lobe and the footprint's Gaussian, seen through the box exactly
            value += edgeWeight * Math.PI * sigmaUv * sigmaUv * density * BoxedEdge.average(dist, hx * Math.abs(nu),
                    hy * Math.abs(nv), Math.sqrt(gaussianVariance), fast);
        }
        if (edgeWeight < 1) {
            Covariance2 spread = g.plus(covariance());
            // a map pixel's box exactly, with the Gaussian's diagonal (exact where the light's plane of incidence
            // follows one of the map's axes, as in the bench's maps); a surface pixel's Gaussian in full
            Covariance2 gaussian = hx > 0 || hy > 0 ? new Covariance2(spread.xx(), 0, spread.yy()) : spread;
            value += (1 - edgeWeight) * LobeGeometry.averagedLobe(sigmaUv, muU, muV, centreU, centreV, hx, hy,
                    gaussian, fast);
        }
        out[0] = gain * value;
        out[1] = -(dz + wr.z());
    }

    /**
     * C S at the direction (dx, dy, d_z) relative to the centre's, d_z^2 = dz2: 0 below the horizon (dz2 <= 0) or
     * where the centre's gain is 0 (lobes_footprint.glsl's discGainRatio).
     */
    private double gainRatio(double dx, double dy, double dz2) {
        if (dz2 <= 0 || centreGain <= 0) {
            return 0;
        }
        Direction d = new Direction(dx, dy, Math.sqrt(Math.max(1e-12, dz2)));
        return GainFactor.gainTimesShadowing(d, wr, refractiveIndex, gainModel) / centreGain;
    }

    private static double smoothstep(double lo, double hi, double x) {
        double t = Math.min(1, Math.max(0, (x - lo) / (hi - lo)));
        return t * t * (3 - 2 * t);
    }

    private static double square(double x) {
        return x * x;
    }
}
