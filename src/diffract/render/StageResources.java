package diffract.render;

import diffract.jrtr.textures.FloatTexture2D;
import diffract.jrtr.GLRenderContext;
import diffract.jrtr.scenegraph.Material;
import diffract.jrtr.scenegraph.RenderList;
import diffract.jrtr.scenegraph.ShaderProgram;
import diffract.jrtr.ShadowMap;
import diffract.jrtr.scenegraph.Shape;
import diffract.jrtr.scenegraph.ShapeNode;
import diffract.jrtr.textures.Texture2D;
import diffract.jrtr.shaders.UniformValue;
import diffract.jrtr.scenegraph.VertexAttribute;
import diffract.jrtr.scenegraph.VertexData;
import diffract.lighting.Environment;
import diffract.lighting.ExtendedLight;
import diffract.optics.BrdfSettings;
import diffract.util.Reporter;

import javax.vecmath.Vector3f;

import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * The GPU side of a {@link Stage} for one shape: the scale frame texture, the key light's shadow map, the ground
 * (a square of {@value #GROUND_HALF_SIZE_RADII} bounding radii under the shape, at its lowest point) and the
 * per-frame uniforms of the staged surface and the ground (environment lights turned with the light, shadow matrix,
 * tone mapping). Used on the render thread.
 */
public final class StageResources {
    /** The ground reaches this many bounding radii from the shape's centre: beyond the frame of any view of it. */
    static final float GROUND_HALF_SIZE_RADII = 12;

    private final Stage stage;
    private final FrameOutput output;
    private final FloatTexture2D scaleFrames;
    private final ShadowMap shadowMap;
    private final ShapeNode groundNode;
    private final Vector3f centre = new Vector3f();
    private final float radius;
    private Environment turned;
    private double turnedDeg = Double.NaN;

    public StageResources(Stage stage, Shape subject) {
        this(stage, subject, FrameOutput.DISPLAY);
    }

    /** The stage of {@code subject}, its surface and ground drawn into frames of {@code output}. */
    public StageResources(Stage stage, Shape subject, FrameOutput output) {
        this.stage = stage;
        this.output = output;
        Stage.ScaleFrames frames = stage.scaleFrames();
        this.scaleFrames = frames == null ? null : new FloatTexture2D(frames.width(), frames.height(), frames.rgba(), true);
        float[] p = subject.vertexData().attribute(VertexAttribute.POSITION);
        float[] min = {Float.MAX_VALUE, Float.MAX_VALUE, Float.MAX_VALUE};
        float[] max = {-Float.MAX_VALUE, -Float.MAX_VALUE, -Float.MAX_VALUE};
        for (int i = 0; i < p.length; i++) {
            min[i % 3] = Math.min(min[i % 3], p[i]);
            max[i % 3] = Math.max(max[i % 3], p[i]);
        }
        centre.set((min[0] + max[0]) / 2, (min[1] + max[1]) / 2, (min[2] + max[2]) / 2);
        radius = (float) Math.max(1e-6, 0.5 * Math.sqrt((max[0] - min[0]) * (max[0] - min[0])
                + (max[1] - min[1]) * (max[1] - min[1]) + (max[2] - min[2]) * (max[2] - min[2])));
        this.shadowMap = stage.shadows() ? new ShadowMap(stage.ground().shadowMapPx()) : null;
        this.groundNode = stage.ground() == null ? null : new ShapeNode(groundShape(min[1]), groundMaterial());
    }

    public Stage stage() {
        return stage;
    }

    /** The ground's node (drawn with the shape), or null. */
    public ShapeNode groundNode() {
        return groundNode;
    }

    /**
     * The staged surface material: the diffraction program with the stage's defines, textures and constants; the
     * lobes method under environment lights wider than it takes bakes its table first, with progress on
     * {@code reporter}.
     */
    public Material surface(DiffractionTextures textures, BrdfSettings settings, float exposure, Texture2D pigmentation,
                            float diffuseWeight, Reporter reporter) {
        Material m = DiffractionMaterials.staged(textures, settings, exposure, pigmentation, diffuseWeight, stage,
                output, reporter);
        if (scaleFrames != null) {
            m.setTexture("scaleFrames", scaleFrames);
        }
        if (shadowMap != null) {
            m.setTexture("shadowMap", shadowMap).setTexture("shadowDepthBounds", shadowMap.depthBounds());
        }
        return m;
    }

    /**
     * Before drawing a frame: renders the shadow map of {@code casters} from the key light and sets the per-frame
     * uniforms on the surface and ground materials; the environment turns about the world y axis by
     * {@code turnDeg} (the key light's direction is given already turned); the key light's size softens the
     * shadow's edges ({@link Stage.Ground#keyLightDiameterDeg}).
     */
    public void beforeFrame(GLRenderContext context, RenderList casters, Vector3f towardsKey, double turnDeg,
                            Material surface) {
        double diameterDeg = stage.ground() == null ? 0 : stage.ground().keyLightDiameterDeg();
        float tanHalf = (float) Math.tan(Math.toRadians(diameterDeg) / 2);
        if (shadowMap != null) {
            shadowMap.aim(towardsKey, centre, radius, tanHalf);
            shadowMap.render(context, casters);
        }
        setFrameUniforms(surface, turnDeg, tanHalf, true);
        if (groundNode != null) {
            setFrameUniforms(groundNode.material(), turnDeg, tanHalf, false);
        }
    }

    /**
     * Tone mapping, shadow and environment uniforms; the extended lights only with {@code extendedLights} (the
     * diffraction surface evaluates the BRDF per light; the Lambertian ground needs only the SH irradiance).
     */
    private void setFrameUniforms(Material m, double turnDeg, float keyLightTanHalfAngle, boolean extendedLights) {
        m.setFloat("toneExposureScale", (float) stage.toneMapping().exposureScale())
                .setFloat("toneWhiteLuminance", (float) stage.toneMapping().whiteLuminance());
        if (shadowMap != null) {
            m.setMatrix("shadowMatrix", shadowMap.lightMatrix()).setFloat("shadowNormalOffset", radius * 2e-3f)
                    .setFloat("shadowTexelWorld", shadowMap.texelWorld())
                    .setFloat("shadowDepthRangeWorld", shadowMap.depthRangeWorld())
                    .setFloat("keyLightTanHalfAngle", keyLightTanHalfAngle);
        }
        Environment environment = environment(turnDeg);
        if (environment != null) {
            m.set("irradianceSh", new UniformValue.Vector3ArrayValue(environment.irradiance().shaderCoefficients()));
        }
        if (environment != null && extendedLights) {
            List<ExtendedLight> lights = environment.lights();
            float[] directions = new float[3 * lights.size()];
            float[] rgb = new float[3 * lights.size()];
            float[] diameters = new float[lights.size()];
            for (int i = 0; i < lights.size(); i++) {
                for (int k = 0; k < 3; k++) {
                    directions[3 * i + k] = (float) lights.get(i).direction()[k];
                    rgb[3 * i + k] = (float) lights.get(i).rgb()[k];
                }
                diameters[i] = (float) lights.get(i).angularDiameterDeg();
            }
            m.set("environmentLightDirection", new UniformValue.Vector3ArrayValue(directions))
                    .set("environmentLightRgb", new UniformValue.Vector3ArrayValue(rgb))
                    .setFloatArray("environmentLightAngularDiameterDeg", diameters);
        }
    }

    private Environment environment(double turnDeg) {
        if (stage.environment() == null) {
            return null;
        }
        if (turnDeg != turnedDeg) {
            turned = stage.environment().rotatedAboutY(turnDeg);
            turnedDeg = turnDeg;
        }
        return turned;
    }

    private Shape groundShape(float y) {
        float h = radius * GROUND_HALF_SIZE_RADII;
        float x0 = centre.x - h;
        float x1 = centre.x + h;
        float z0 = centre.z - h;
        float z1 = centre.z + h;
        float[] positions = {x0, y, z0, x1, y, z0, x1, y, z1, x0, y, z1};
        float[] normals = {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0};
        float[] tangents = {1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0};
        float[] uvs = {0, 0, 1, 0, 1, 1, 0, 1};
        return new Shape("ground", VertexData.builder(4).positions(positions).normals(normals).tangents(tangents)
                .texcoords(uvs).indices(new int[] {0, 2, 1, 0, 3, 2}).build());
    }

    private Material groundMaterial() {
        Map<String, String> defines = new TreeMap<>(stage.defines());
        output.addDefines(defines);
        ShaderProgram program = ShaderProgram.fromClasspath("lighting/ground.vert", "lighting/ground.frag", defines);
        Stage.Ground g = stage.ground();
        Material m = new Material(program)
                .setVec3("albedoLinear", (float) g.albedoLinear()[0], (float) g.albedoLinear()[1],
                        (float) g.albedoLinear()[2])
                .setFloat("mottle", (float) g.mottle())
                .setFloat("mottleScale", 12 / radius);
        if (shadowMap != null) {
            m.setTexture("shadowMap", shadowMap).setTexture("shadowDepthBounds", shadowMap.depthBounds());
        }
        return m;
    }

    /** Frees the stage's textures and programs (the context is about to go or the stage is replaced). */
    public void release(GLRenderContext context) {
        if (scaleFrames != null) {
            context.release(scaleFrames);
        }
        if (shadowMap != null) {
            context.release(shadowMap);
        }
        if (groundNode != null) {
            context.release(groundNode.material().program());
        }
    }
}
