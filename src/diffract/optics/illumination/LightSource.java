package diffract.optics.illumination;

import diffract.optics.numerics.Covariance2;
import diffract.optics.patches.Direction;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.LightProfile;
import diffract.optics.settings.Quantity;

/**
 * A distant light of angular diameter D (the sun: 0.53 degrees; a lamp or a window: several) and its profile.
 *
 * <p>{@link LightProfile#DISC} (the default): uniform radiance over the cone of half-angle D / 2 around omega_i, what
 * a scene's sun, lamp or softbox is. The reference averages the relative BRDF over the cone's directions, each
 * evaluated exactly ({@code DiscLightAverage}); the lobes method averages each lobe over the cone's
 * ellipse in (u, v) with C, S and w per direction ({@link DiscFootprint}).
 *
 * <p>{@link LightProfile#GAUSSIAN} (kept for comparisons, and the profile of an environment's lights): a Gaussian over
 * the light's directions in the tangent plane of the unit sphere at its centre omega_i, with per-axis angular
 * standard deviation sigma_a = D / 4, the standard deviation of a uniform disk of diameter D along any axis. A
 * direction offset by (a, b) along the polar basis vector e_theta = (cos t cos p, cos t sin p, -sin t) and the azimuthal one
 * e_phi = (-sin p, cos p, 0) moves (u, v) = -omega_i.xy - omega_r.xy by -(a e_theta.xy + b e_phi.xy): to first
 * order a Gaussian in (u, v) of covariance sigma_a^2 J J^T, J = [e_theta.xy, e_phi.xy] = sigma_a^2 (cos^2 t r r^T +
 * e e^T), r = (cos p, sin p), e = (-sin p, cos p): an ellipse cos(theta_i) times shorter in the plane of incidence.
 * The gain factor, the shadowing and w stay at the light's centre. Against the disc it differs by the disc's flat
 * top (a Gaussian of equal variance puts 13.5 % of its power outside the diameter) and by the linearisation, of
 * relative size sigma_a: docs/measurements/filtering.md measures the two apart.
 */
public record LightSource(double angularDiameterDeg, LightProfile profile) {
    /** The sun seen from the earth: 0.53 degrees. */
    public static final double SUN_DEG = 0.53;
    /** The largest diameter accepted: beyond it the linearised profile stops describing the light. */
    public static final double MAX_DIAMETER_DEG = 20;
    public static final LightSource POINT = new LightSource(0);

    public LightSource {
        if (profile == null) {
            throw new NullPointerException("the light's profile is required");
        }
        if (!(angularDiameterDeg >= 0) || !(angularDiameterDeg <= MAX_DIAMETER_DEG)) {
            throw new InvalidSettingException(Quantity.LIGHT_SIZE, Quantity.LIGHT_SIZE.words() + " must be in [0, "
                    + InvalidSettingException.number(MAX_DIAMETER_DEG) + "] degrees, got " + angularDiameterDeg);
        }
    }

    /** A disc light (the default profile) of angular diameter D degrees. */
    public LightSource(double angularDiameterDeg) {
        this(angularDiameterDeg, LightProfile.DISC);
    }

    /** This light's diameter with {@code p}. */
    public LightSource withProfile(LightProfile p) {
        return new LightSource(angularDiameterDeg, p);
    }

    /**
     * "LightSource[point]" for a point light, whose profile changes nothing, else the record's components: the form
     * in which the disk cache's keys (IlluminationSettings in words) name the light, so that a point light's maps and
     * tables are found whatever profile its settings carry.
     */
    @Override
    public String toString() {
        return isPoint() ? "LightSource[point]"
                : "LightSource[angularDiameterDeg=" + angularDiameterDeg + ", profile=" + profile + "]";
    }

    /** A light of finite size whose radiance is uniform over its disc (a point light is the same under both). */
    public boolean isDisc() {
        return profile == LightProfile.DISC && !isPoint();
    }

    /** The cone's half-angle D / 2 in radians. */
    public double halfAngleRad() {
        return Math.toRadians(angularDiameterDeg) / 2.0;
    }

    public boolean isPoint() {
        return angularDiameterDeg == 0;
    }

    /** sigma_a = D / 4 in radians. */
    public double sigmaRad() {
        return sigmaRadOf(angularDiameterDeg);
    }

    /** sigma_a = D / 4 in radians of a light of angular diameter D degrees (any D: an environment's lights too). */
    public static double sigmaRadOf(double angularDiameterDeg) {
        return Math.toRadians(angularDiameterDeg) / 4.0;
    }

    /**
     * The covariance in (u, v) of the Gaussian profile's directions around omega_i (see the class comment); a disc
     * light has none (the reference integrates its directions, {@code DiscLightAverage}) and gives
     * zero.
     */
    public Covariance2 uvCovariance(Direction wi) {
        if (isPoint() || isDisc()) {
            return Covariance2.ZERO;
        }
        double variance = sigmaRad() * sigmaRad();
        double sinTheta = Math.hypot(wi.x(), wi.y());
        double cosTheta = wi.z();
        if (sinTheta < 1e-12) {
            return Covariance2.isotropic(variance);
        }
        double rx = wi.x() / sinTheta;
        double ry = wi.y() / sinTheta;
        return Covariance2.along(rx, ry, variance * cosTheta * cosTheta).plus(Covariance2.along(-ry, rx, variance));
    }
}
