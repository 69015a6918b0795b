package diffract.lighting;

/**
 * A distant light of finite size, as the median cut makes them: a direction, the light it delivers and the solid
 * angle it stands for. The diffraction shaders treat it as a directional light of irradiance {@code rgb} (towards
 * it, in units of the key light) today; {@code angularDiameterDeg} is there for a BRDF that filters by light size.
 *
 * @param direction          unit vector towards the light, world frame (y up)
 * @param rgb                linear RGB irradiance delivered to a surface facing the light (integral of radiance
 *                           over the light's solid angle)
 * @param solidAngleSr       the solid angle the light stands for, steradians
 * @param angularDiameterDeg the diameter of a disc of that solid angle as seen from the surface, degrees:
 *                           2 acos(1 - solidAngle / (2 pi))
 */
public record ExtendedLight(double[] direction, double[] rgb, double solidAngleSr, double angularDiameterDeg) {
    public ExtendedLight {
        direction = direction.clone();
        rgb = rgb.clone();
    }

    /** A light of this solid angle, its angular diameter computed. */
    public static ExtendedLight of(double[] direction, double[] rgb, double solidAngleSr) {
        double cos = Math.max(-1, 1 - solidAngleSr / (2 * Math.PI));
        return new ExtendedLight(direction, rgb, solidAngleSr, Math.toDegrees(2 * Math.acos(cos)));
    }

    /** Luminance of {@code rgb} (Rec. 709 weights). */
    public double luminance() {
        return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
    }
}
