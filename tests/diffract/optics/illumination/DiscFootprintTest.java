package diffract.optics.illumination;

import diffract.optics.patches.Direction;
import diffract.optics.settings.GainModel;
import net.jqwik.api.Assume;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.DoubleRange;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@link DiscFootprint#gainBound}, which the lobes method's cutoff multiplies: the gain relative to the centre's at
 * directions spread over the whole cone (not the rim samples the bound reads) never exceeds it, and a small disc's
 * bound is close to 1, so that the cutoff culls as it does under a point light.
 */
class DiscFootprintTest {
    static final double REFRACTIVE_INDEX = 1.5;

    @Property(tries = 300)
    void noDirectionOfTheDiscHasAGainAboveTheBound(@ForAll @DoubleRange(min = 0.53, max = 20) double diameterDeg,
                                                 @ForAll @DoubleRange(min = 0, max = 70) double thetaIDeg,
                                                 @ForAll @DoubleRange(min = 0, max = 360) double phiIDeg,
                                                 @ForAll @DoubleRange(min = 0, max = 80) double thetaRDeg,
                                                 @ForAll @DoubleRange(min = 0, max = 360) double phiRDeg,
                                                 @ForAll GainModel fresnel) {
        Direction wi = Direction.fromSphericalDeg(thetaIDeg, phiIDeg);
        Direction wr = Direction.fromSphericalDeg(thetaRDeg, phiRDeg);
        double centre = GainFactor.gainTimesShadowing(wi, wr, REFRACTIVE_INDEX, fresnel);
        Assume.that(centre > 0);
        DiscFootprint disc = new DiscFootprint(new LightSource(diameterDeg), wi, wr, REFRACTIVE_INDEX, fresnel);
        double bound = disc.gainBound();
        double largest = largestRatioOverTheCone(wi, wr, Math.toRadians(diameterDeg / 2), fresnel, centre);
        assertTrue(largest <= bound * (1 + 1e-9), "largest gain ratio " + largest + " above the bound " + bound);
    }

    @Property(tries = 100)
    void theSunsBoundIsWithinAFewPerCentOfOne(@ForAll @DoubleRange(min = 0, max = 60) double thetaIDeg,
                                             @ForAll @DoubleRange(min = 0, max = 60) double thetaRDeg,
                                             @ForAll @DoubleRange(min = 0, max = 360) double phiRDeg) {
        Direction wi = Direction.fromSphericalDeg(thetaIDeg, 0);
        Direction wr = Direction.fromSphericalDeg(thetaRDeg, phiRDeg);
        Assume.that(GainFactor.gainTimesShadowing(wi, wr, REFRACTIVE_INDEX, GainModel.STAM) > 0);
        double bound = new DiscFootprint(new LightSource(LightSource.SUN_DEG), wi, wr, REFRACTIVE_INDEX,
                GainModel.STAM).gainBound();
        assertTrue(bound >= 1 && bound <= 1.05, "the sun's bound " + bound);
    }

    /**
     * The largest gain ratio at directions cos(alpha) omega_i + sin(alpha) (cos(beta) e + sin(beta) t) of the cone,
     * alpha on 24 rings up to R and beta at 96 azimuths (e horizontal, t completing the frame about omega_i).
     */
    private static double largestRatioOverTheCone(Direction wi, Direction wr, double halfAngleRad,
                                                  GainModel fresnel, double centre) {
        double sinTheta = Math.hypot(wi.x(), wi.y());
        double rx = sinTheta < 1e-12 ? 1 : wi.x() / sinTheta;
        double ry = sinTheta < 1e-12 ? 0 : wi.y() / sinTheta;
        double[] e = {-ry, rx, 0};
        double[] t = {wi.z() * rx, wi.z() * ry, -sinTheta};
        double largest = 0;
        for (int ring = 1; ring <= 24; ring++) {
            double alpha = halfAngleRad * ring / 24;
            for (int k = 0; k < 96; k++) {
                double beta = 2 * Math.PI * k / 96;
                double c = Math.cos(alpha);
                double s = Math.sin(alpha);
                double dx = c * wi.x() + s * (Math.cos(beta) * e[0] + Math.sin(beta) * t[0]);
                double dy = c * wi.y() + s * (Math.cos(beta) * e[1] + Math.sin(beta) * t[1]);
                double dz = c * wi.z() + s * (Math.cos(beta) * e[2] + Math.sin(beta) * t[2]);
                if (dz <= 0) {
                    continue;
                }
                double gain = GainFactor.gainTimesShadowing(new Direction(dx, dy, dz), wr, REFRACTIVE_INDEX, fresnel);
                largest = Math.max(largest, gain / centre);
            }
        }
        return largest;
    }
}
