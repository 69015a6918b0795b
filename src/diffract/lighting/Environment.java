package diffract.lighting;

import java.util.ArrayList;
import java.util.List;

/**
 * An environment ready for the shaders: the map (kept small: its detail is in the lights), the extended lights the
 * median cut draws from it and its diffuse irradiance. {@link #rotatedAboutY} turns all three together, for a light
 * that goes round the subject.
 */
public final class Environment {
    /** The map is averaged down to at most this width before the median cut and the harmonics. */
    static final int WORKING_WIDTH = 256;

    private final LatLongMap map;
    private final int rounds;
    private final List<ExtendedLight> lights;
    private final ShIrradiance irradiance;

    /** @param rounds median-cut rounds: 2^rounds extended lights */
    public Environment(LatLongMap map, int rounds) {
        this.map = map.downsampled(Math.max(1, map.width() / WORKING_WIDTH));
        this.rounds = rounds;
        this.lights = List.copyOf(MedianCut.lights(this.map, rounds));
        this.irradiance = ShIrradiance.of(this.map);
    }

    private Environment(LatLongMap map, int rounds, List<ExtendedLight> lights, ShIrradiance irradiance) {
        this.map = map;
        this.rounds = rounds;
        this.lights = lights;
        this.irradiance = irradiance;
    }

    public LatLongMap map() {
        return map;
    }

    public List<ExtendedLight> lights() {
        return lights;
    }

    public ShIrradiance irradiance() {
        return irradiance;
    }

    /**
     * The environment turned about the world y axis by {@code degrees} (counter-clockwise seen from above): the
     * lights' directions turn exactly; the irradiance is projected again from the turned map.
     */
    public Environment rotatedAboutY(double degrees) {
        if (degrees % 360 == 0) {
            return this;
        }
        double c = Math.cos(Math.toRadians(degrees));
        double s = Math.sin(Math.toRadians(degrees));
        List<ExtendedLight> turned = new ArrayList<>();
        for (ExtendedLight l : lights) {
            double[] d = l.direction();
            turned.add(new ExtendedLight(new double[] {c * d[0] + s * d[2], d[1], -s * d[0] + c * d[2]}, l.rgb(),
                    l.solidAngleSr(), l.angularDiameterDeg()));
        }
        LatLongMap turnedMap = map.rotatedAboutY(degrees);
        return new Environment(turnedMap, rounds, List.copyOf(turned), ShIrradiance.of(turnedMap));
    }
}
