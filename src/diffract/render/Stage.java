package diffract.render;

import diffract.colour.ToneMapping;
import diffract.lighting.Environment;
import diffract.lighting.ExtendedLight;

import java.util.Map;
import java.util.TreeMap;

/**
 * Where a surface is shown, beyond its BRDF: the scales' frame map, the environment's light, a ground with the key
 * light's shadow, and the tone mapping of the result. {@link #none()} is the plain surface of the thesis (no
 * staging: the shaders are compiled exactly as without it).
 *
 * @param scaleFrames  the frame map of {@link diffract.geometry.ScaledSkin#frameMap}, or null for the mesh's frame
 * @param environment  extended lights and diffuse irradiance, or null
 * @param ground       the ground under the shape, or null
 * @param toneMapping  from linear light to the display
 * @param glossyAlpha  null for the diffraction BRDF; else the scales are a glossy dielectric (GGX of this roughness,
 *                     the patch's refractive index) in its place, all else staged alike: the cost of diffraction
 *                     beside a standard material ({@link #withGlossyScales})
 */
public record Stage(ScaleFrames scaleFrames, Environment environment, Ground ground, ToneMapping toneMapping,
                    Double glossyAlpha) {
    /** Most extended lights the surface shader evaluates (each one costs a full BRDF evaluation per fragment). */
    public static final int MAX_ENVIRONMENT_LIGHTS = 16;

    /** RGBA floats, width x height, row 0 at texture coordinate v = 0. */
    public record ScaleFrames(int width, int height, float[] rgba) {
    }

    /**
     * @param albedoLinear linear sRGB albedo
     * @param mottle       relative amplitude of the albedo's noise, 0..1
     * @param shadows      whether the key light casts shadows (on the ground and the shape)
     * @param shadowMapPx  side of the shadow map, texels
     * @param keyLightDiameterDeg the key light's angular diameter as the scene gives it, whatever a variant that
     *                     samples the light at its centre draws the BRDF with: the shadow's penumbra
     */
    public record Ground(double[] albedoLinear, double mottle, boolean shadows, int shadowMapPx,
                         double keyLightDiameterDeg) {
    }

    public Stage {
        if (toneMapping == null) {
            throw new IllegalArgumentException("a stage needs a tone mapping (ToneMapping.clip() for none)");
        }
        if (environment != null && environment.lights().size() > MAX_ENVIRONMENT_LIGHTS) {
            throw new IllegalArgumentException(environment.lights().size() + " environment lights; at most "
                    + MAX_ENVIRONMENT_LIGHTS);
        }
    }

    /** The diffraction BRDF on this stage. */
    public Stage(ScaleFrames scaleFrames, Environment environment, Ground ground, ToneMapping toneMapping) {
        this(scaleFrames, environment, ground, toneMapping, null);
    }

    public static Stage none() {
        return new Stage(null, null, null, ToneMapping.clip());
    }

    /**
     * The same stage with the scales as a glossy dielectric of GGX roughness {@code alpha} in place of the
     * diffraction BRDF (Cook-Torrance, engine/ggx.glsl): the lights, the ground, the shadow and the pigment stay.
     */
    public Stage withGlossyScales(double alpha) {
        if (!(alpha > 0 && alpha <= 1)) {
            throw new IllegalArgumentException("GGX roughness must be in (0, 1], got " + alpha);
        }
        return new Stage(scaleFrames, environment, ground, toneMapping, alpha);
    }

    /** Whether anything is staged: otherwise the surface shader is the thesis' own. */
    public boolean staged() {
        return scaleFrames != null || environment != null || ground != null || glossyAlpha != null
                || toneMapping.operator() != ToneMapping.Operator.CLIP || toneMapping.exposureStops() != 0;
    }

    public boolean shadows() {
        return ground != null && ground.shadows();
    }

    /** The angular diameter of the environment's widest extended light, degrees (0 without an environment). */
    public double widestEnvironmentLightDeg() {
        return environment == null ? 0 : environment.lights().stream()
                .mapToDouble(ExtendedLight::angularDiameterDeg).max().orElse(0);
    }

    /** The compile-time switches of surface_stage.glsl and the ground shader. */
    public Map<String, String> defines() {
        Map<String, String> d = new TreeMap<>();
        if (!staged()) {
            return d;
        }
        d.put("STAGE", "1");
        if (scaleFrames != null) {
            d.put("SCALE_FRAMES", "1");
        }
        if (environment != null) {
            d.put("ENVIRONMENT_LIGHTS", Integer.toString(environment.lights().size()));
            d.put("IRRADIANCE_SH", "1");
        }
        if (shadows()) {
            d.put("SHADOW_MAP", "1");
        }
        if (glossyAlpha != null) {
            d.put("GGX_ALPHA", Float.toString(glossyAlpha.floatValue()));
        }
        d.put("TONE_MAP_OPERATOR", Integer.toString(toneMapping.operator().ordinal()));
        return d;
    }
}
