package diffract.optics;

import diffract.colour.Xyz;
import diffract.optics.patches.Direction;
import diffract.optics.illumination.Footprint;
import diffract.optics.illumination.LightSource;
import diffract.optics.numerics.Covariance2;
import diffract.optics.numerics.GaussLegendre;
import diffract.optics.settings.LightProfile;

/**
 * The filtered reference under a disc light ({@link LightProfile#DISC}): the relative BRDF averaged uniformly over
 * the solid angle of the cone of half-angle R = D / 2 around the light's direction omega_i, every quantity (C, S,
 * w, u, v) evaluated at each incident direction by the point-light reference ({@link FilteredReference}, with its
 * pixel box and exact wavelength integral).
 *
 * <p>Why uniform over solid angle: the relative BRDF is f cos theta_i up to a constant (docs/design/theory.md), so a light
 * of uniform radiance L over the cone reflects L integral f cos theta_i d omega = L Omega times the solid-angle
 * average of the relative BRDF; divided by L Omega, the light's strength as a point light of the same L Omega would
 * carry, the map keeps the point light's scale and the incident cosine enters per direction through C.
 *
 * <p>Quadrature: with t = (1 - cos alpha) / (1 - cos R) and beta the azimuth about omega_i, d omega =
 * (1 - cos R) dt d beta, so the average is (1 / 2 pi) integral_0^1 dt integral_0^2pi d beta. Gauss-Legendre in t
 * ({@link GaussLegendre}; a smooth function of the tangent plane, averaged over beta, is smooth in alpha^2 and so in
 * t) and the trapezoid rule in beta (spectrally accurate on a periodic integrand), at n = 2, 4, 8, ... radial nodes
 * and {@link #AZIMUTHS_PER_RADIAL} n azimuths, the azimuths of every other ring offset by half a step. A pixel is
 * accepted where two successive rules agree to {@link FilteredReference#PIXEL_TOLERANCE} of its largest tristimulus
 * value plus {@link FilteredReference#FLOOR}, up to {@link #MAX_RADIAL_NODES} radial nodes, from a rule whose nodes
 * lie at most half a pixel apart ({@link #fewestRadialNodes}). Directions below the horizon light nothing but keep
 * their share of the cone (the light is partly set).
 */
public final class DiscLightAverage {
    /** Azimuths per radial node: the rings' circumference grows as sqrt(t), so 3 n is enough for the outer rings. */
    static final int AZIMUTHS_PER_RADIAL = 3;
    /** The finest rule: 32 radial nodes x 96 azimuths. */
    static final int MAX_RADIAL_NODES = 32;

    private final FilteredReference reference;
    private final double halfAngleRad;

    public DiscLightAverage(FilteredReference reference, LightSource light) {
        if (!light.isDisc()) {
            throw new IllegalArgumentException("a disc light of finite size is required, got " + light);
        }
        this.reference = reference;
        this.halfAngleRad = light.halfAngleRad();
    }

    /** What one incident direction gives: {X, Y, Z}. */
    @FunctionalInterface
    interface PerDirection {
        double[] at(Direction wi);
    }

    /** Pixel (column, row) of an S x S map ({@link BrdfMap}'s convention) averaged over the disc around omega_i. */
    public Xyz mapPixel(Direction wi, int column, int row, int size) {
        return mapPixelRules(wi, column, row, size).value();
    }

    /**
     * What the adaptive rule gives: the accepted value, the rule before it (their difference is the rule's estimate
     * of its error, above the tolerance where the finest rule stopped it) and the finest rule's radial nodes.
     */
    public record Rules(Xyz value, Xyz coarser, int radialNodes) {
        /** Whether the last two rules agreed to the tolerance, not the finest rule stopping them. */
        public boolean converged() {
            return agree(value, coarser);
        }
    }

    /** {@link #mapPixel} with the rule's own estimate of its error. */
    public Rules mapPixelRules(Direction wi, int column, int row, int size) {
        double x = BrdfMap.xOf(column, size);
        double y = BrdfMap.yOf(row, size);
        if (x * x + y * y >= 1) {
            Xyz zero = new Xyz(0, 0, 0);
            return new Rules(zero, zero, 0);
        }
        return rules(wi, d -> {
            Xyz c = reference.mapPixel(d, Covariance2.ZERO, column, row, size);
            return new double[] {c.x(), c.y(), c.z()};
        }, fewestRadialNodes(halfAngleRad, size));
    }

    /**
     * The fewest radial nodes a pixel of an S x S map starts from: the rim's azimuths at most half a pixel (2 / S in
     * x and y) apart, up to {@link #MAX_RADIAL_NODES}. Seen from one pixel, the directions of a disc that light it
     * through a narrow order form a patch about a pixel wide; coarser rules can miss it at every node and agree on
     * 0, which would end the rule at a black pixel.
     */
    static int fewestRadialNodes(double halfAngleRad, int size) {
        double rimSpacing = 2 * Math.PI * Math.sin(halfAngleRad) / AZIMUTHS_PER_RADIAL;
        int n = 1;
        while (n < MAX_RADIAL_NODES && rimSpacing / n > 1.0 / size) {
            n *= 2;
        }
        return n;
    }

    /** The point direction omega_r (no pixel) averaged over the disc around omega_i. */
    public Xyz at(Direction wi, Direction wr) {
        return average(wi, d -> reference.at(d, wr, Footprint.POINT));
    }

    /** The adaptive rule of the class comment. */
    Xyz average(Direction wi, PerDirection f) {
        return rules(wi, f, 1).value();
    }

    /** The adaptive rule from {@code fewest} radial nodes (a power of two), checked against half as many. */
    private Rules rules(Direction wi, PerDirection f, int fewest) {
        int first = Math.max(2, fewest);
        Xyz previous = xyz(rule(wi, f, first / 2));
        for (int n = first; ; n *= 2) {
            Xyz current = xyz(rule(wi, f, n));
            if (agree(current, previous) || n >= MAX_RADIAL_NODES) {
                return new Rules(current, previous, n);
            }
            previous = current;
        }
    }

    /** Two rules agree to {@link FilteredReference#PIXEL_TOLERANCE} of the larger tristimulus value plus the floor. */
    static boolean agree(Xyz current, Xyz previous) {
        double scale = Math.max(Math.abs(current.x()), Math.max(Math.abs(current.y()), Math.abs(current.z())));
        double tolerance = FilteredReference.PIXEL_TOLERANCE * scale + FilteredReference.FLOOR;
        return Math.abs(current.x() - previous.x()) <= tolerance && Math.abs(current.y() - previous.y()) <= tolerance
                && Math.abs(current.z() - previous.z()) <= tolerance;
    }

    private static Xyz xyz(double[] v) {
        return new Xyz(v[0], v[1], v[2]);
    }

    /** n radial Gauss-Legendre nodes in t times 3 n trapezoid azimuths. */
    double[] rule(Direction wi, PerDirection f, int n) {
        double[][] gl = GaussLegendre.unitInterval(n);
        int azimuths = AZIMUTHS_PER_RADIAL * n;
        double[][] basis = tangentBasis(wi);
        double oneMinusCosR = 1 - Math.cos(halfAngleRad);
        double[] sum = new double[3];
        for (int i = 0; i < n; i++) {
            double cosAlpha = 1 - gl[0][i] * oneMinusCosR;
            double sinAlpha = Math.sqrt(Math.max(0, 1 - cosAlpha * cosAlpha));
            double offset = (i % 2) * 0.5;
            for (int j = 0; j < azimuths; j++) {
                double beta = 2 * Math.PI * (j + offset) / azimuths;
                Direction d = direction(wi, basis, cosAlpha, sinAlpha, beta);
                if (d.z() <= 0) {
                    continue;
                }
                double[] value = f.at(d);
                double weight = gl[1][i] / azimuths;
                for (int k = 0; k < 3; k++) {
                    sum[k] += weight * value[k];
                }
            }
        }
        return sum;
    }

    /**
     * The direction at angle alpha from omega_i and azimuth beta about it: cos alpha omega_i + sin alpha (cos beta
     * e_theta + sin beta e_phi), with LightSource's polar and azimuthal basis vectors (any orthonormal pair at the
     * normal).
     */
    static Direction direction(Direction wi, double[][] basis, double cosAlpha, double sinAlpha, double beta) {
        double c = Math.cos(beta) * sinAlpha;
        double s = Math.sin(beta) * sinAlpha;
        double x = cosAlpha * wi.x() + c * basis[0][0] + s * basis[1][0];
        double y = cosAlpha * wi.y() + c * basis[0][1] + s * basis[1][1];
        double z = cosAlpha * wi.z() + c * basis[0][2] + s * basis[1][2];
        double norm = Math.sqrt(x * x + y * y + z * z);
        return new Direction(x / norm, y / norm, z / norm);
    }

    /** e_theta = (cos t cos p, cos t sin p, -sin t) and e_phi = (-sin p, cos p, 0) of omega_i; x and y at the normal. */
    static double[][] tangentBasis(Direction wi) {
        double sinTheta = Math.hypot(wi.x(), wi.y());
        if (sinTheta < 1e-12) {
            return new double[][] {{1, 0, 0}, {0, 1, 0}};
        }
        double cp = wi.x() / sinTheta;
        double sp = wi.y() / sinTheta;
        return new double[][] {{wi.z() * cp, wi.z() * sp, -sinTheta}, {-sp, cp, 0}};
    }
}
