package diffract.viewer;

import com.jogamp.opengl.GLAutoDrawable;
import diffract.colour.Srgb;
import diffract.jrtr.scenegraph.Camera;
import diffract.jrtr.scenegraph.Frustum;
import diffract.jrtr.scenegraph.Group;
import diffract.jrtr.scenegraph.LightNode;
import diffract.jrtr.scenegraph.Material;
import diffract.jrtr.scenegraph.RenderItem;
import diffract.jrtr.scenegraph.RenderList;
import diffract.jrtr.Renderer;
import diffract.jrtr.scenegraph.ShaderProgram;
import diffract.jrtr.scenegraph.ShapeNode;
import diffract.jrtr.scenegraph.Shapes;
import diffract.jrtr.textures.Texture2D;
import diffract.optics.BrdfSettings;
import diffract.optics.patches.Direction;
import diffract.render.DiffractionMaterials;
import diffract.render.FrameOutput;
import diffract.render.StageResources;
import diffract.scene.DisplayMode;
import diffract.scene.OrbitCamera;

import javax.vecmath.Point3f;
import javax.vecmath.Vector3f;
import java.util.Map;

/**
 * Draws the model: each frame reads one {@link ViewerState} and shows either the shape with the diffraction surface
 * material seen from the orbit camera (the shader takes omega_r from each fragment to this frame's camera
 * position, so the shading follows the camera), or the BRDF map of the current light, centred in the viewport.
 * As a GLEventListener it draws whole frames of the model's state, for {@code diffract render} into an offscreen
 * target; the viewer's window draws through {@link RefiningRenderer}, which prepares a frame of a state and
 * settings of its choice ({@link #prepareFrame}) and draws it in tiles ({@link #displayTile}).
 */
public final class ViewerRenderer extends Renderer {
    /** Grey, not black: a black background would hide where the surface reflects nothing. */
    public static final float[] CLEAR_COLOUR = {0.12f, 0.12f, 0.14f, 1f};

    private final ViewerModel model;
    private final Texture2D pigmentationTexture;
    private final ViewerMaterials materials;
    private final FrameStats stats = new FrameStats();
    private final LightNode light = new LightNode("light", new Vector3f(0, 0, 1), new Vector3f(1, 1, 1));
    private final ShapeNode surface;
    private final Group surfaceScene;
    private final ShapeNode mapQuad;
    private final Group mapScene;
    /** The stage's GPU side (scales, environment, ground, shadow), or null for the plain surface. */
    private final StageResources stage;
    private final Group casters;
    private final Group maskScene;
    /** The background: {@link #CLEAR_COLOUR}, or its linear value in frames of linear light. */
    private final float[] clearColour;
    private Material maskMaterial;
    private volatile boolean maskOnly;
    private volatile double lightTurnDeg;
    private int widthPx;
    private int heightPx;

    public ViewerRenderer(ViewerModel model) {
        this(model, FrameOutput.DISPLAY);
    }

    /**
     * Frames of {@code output}: display values (what a window shows), or linear light for a still kept as floats,
     * the background then the linear value of the display's grey.
     */
    public ViewerRenderer(ViewerModel model, FrameOutput output) {
        super(new Group("viewer"), new Camera(), new Frustum(0.05f, 100f, 1f, (float) model.setup().verticalFovDeg()));
        this.model = model;
        this.pigmentationTexture = model.pigmentationImage().map(Texture2D::new).orElse(null);
        this.materials = new ViewerMaterials(pigmentationTexture, model.setup().diffuseWeight(), model.pipeline(),
                output);
        this.clearColour = output == FrameOutput.LINEAR ? linear(CLEAR_COLOUR) : CLEAR_COLOUR;
        // the nodes get their materials on the render thread, at the first frame
        this.surface = new ShapeNode(model.shape(), null);
        this.surfaceScene = new Group("surface").add(light, surface);
        this.casters = new Group("shadow casters").add(new ShapeNode(model.shape(), null));
        this.maskScene = new Group("mask").add(new ShapeNode(model.shape(), null));
        this.stage = model.setup().stage().staged() ? new StageResources(model.setup().stage(), model.shape(), output)
                : null;
        if (stage != null) {
            materials.useStage(stage);
            if (stage.groundNode() != null) {
                surfaceScene.add(stage.groundNode());
            }
        }
        this.mapQuad = new ShapeNode(Shapes.fullScreenQuad(), null);
        this.mapScene = new Group("brdf map").add(mapQuad);
        setClearColor(clearColour[0], clearColour[1], clearColour[2], clearColour[3]);
    }

    /** Display-encoded sRGB and alpha to linear sRGB and alpha. */
    private static float[] linear(float[] displayRgba) {
        return new float[] {(float) Srgb.decode(displayRgba[0]), (float) Srgb.decode(displayRgba[1]),
                (float) Srgb.decode(displayRgba[2]), displayRgba[3]};
    }

    /**
     * Turns the key light (and the environment with it) about the world y axis by {@code degrees} from the state's
     * light: a light going round the subject, for turntables.
     */
    public void setLightTurnDeg(double degrees) {
        lightTurnDeg = degrees;
    }

    /**
     * With {@code on}, frames show only the shape, white on black, unlit: the mask of where the subject is in the
     * picture (for measurements of the picture).
     */
    public void setMaskOnly(boolean on) {
        maskOnly = on;
    }

    public FrameStats stats() {
        return stats;
    }

    /** Materials built so far: changes only when settings that need a new program or textures change. */
    public int materialBuildCount() {
        return materials.rebuildCount();
    }

    @Override
    public void reshape(GLAutoDrawable drawable, int x, int y, int width, int height) {
        widthPx = width;
        heightPx = height;
        super.reshape(drawable, x, y, width, height);
    }

    /** One whole frame of the model's current state, as configured. */
    @Override
    public void display(GLAutoDrawable drawable) {
        long start = System.nanoTime();
        ViewerState state = model.state();
        if (maskOnly) {
            showMask(drawable);
            return;
        }
        prepareFrame(state, state.drawableSettings(), widthPx, heightPx);
        super.display(drawable);
        context().gl().glFinish(); // so the frame time includes the GPU's work, not just issuing it
        stats.record((System.nanoTime() - start) / 1e6);
    }

    /**
     * Sets up a frame of {@code state} drawn with {@code settings} (the state's own, or a cheaper preview's) in a
     * viewport of {@code widthPx} x {@code heightPx}: the material (built if not at hand), camera, light and the
     * stage's shadow map. Its tiles are then drawn with {@link #displayTile}. On the render thread.
     */
    void prepareFrame(ViewerState state, BrdfSettings settings, int widthPx, int heightPx) {
        Material material = materials.materialFor(state, settings, context());
        // the lobes method's cutoff follows the exposure keys: a brighter picture shows dimmer lobes
        DiffractionMaterials.setExposure(material, settings, state.view().exposure());
        if (state.view().mode() == DisplayMode.BRDF_MAP) {
            showBrdfMap(state, settings, material, widthPx, heightPx);
        } else {
            showSurface(state, material);
        }
    }

    private void showSurface(ViewerState state, Material material) {
        double[] eye = state.view().camera().eye();
        OrbitCamera orbit = state.view().camera();
        camera().set(new Point3f((float) eye[0], (float) eye[1], (float) eye[2]),
                new Point3f((float) orbit.targetX(), (float) orbit.targetY(), (float) orbit.targetZ()),
                new Vector3f(0, 1, 0));
        Direction towardsLight = state.view().light().direction();
        double turn = Math.toRadians(lightTurnDeg);
        // turned about +y: (x, z) -> (x cos + z sin, -x sin + z cos), as Environment.rotatedAboutY
        Vector3f towards = new Vector3f((float) (towardsLight.x() * Math.cos(turn) + towardsLight.z() * Math.sin(turn)),
                (float) towardsLight.y(), (float) (-towardsLight.x() * Math.sin(turn) + towardsLight.z() * Math.cos(turn)));
        light.setDirection(towards);
        surface.setMaterial(material);
        if (stage != null && state.view().mode() == DisplayMode.SURFACE) {
            stage.beforeFrame(context(), RenderList.collect(casters), towards, lightTurnDeg, material);
        }
        setRoot(surfaceScene);
    }

    private void showMask(GLAutoDrawable drawable) {
        if (maskMaterial == null) {
            maskMaterial = new Material(ShaderProgram.fromClasspath("engine/unlit.vert", "engine/unlit.frag",
                    Map.of())).setVec4("color", 1, 1, 1, 1);
            for (RenderItem item : RenderList.collect(maskScene).items()) {
                ((ShapeNode) item.node()).setMaterial(maskMaterial);
            }
        }
        double[] eye = model.state().view().camera().eye();
        OrbitCamera orbit = model.state().view().camera();
        camera().set(new Point3f((float) eye[0], (float) eye[1], (float) eye[2]),
                new Point3f((float) orbit.targetX(), (float) orbit.targetY(), (float) orbit.targetZ()),
                new Vector3f(0, 1, 0));
        setRoot(maskScene);
        setClearColor(0, 0, 0, 1);
        super.display(drawable);
        setClearColor(clearColour[0], clearColour[1], clearColour[2], clearColour[3]);
        context().gl().glFinish();
    }

    /**
     * The largest square map that fits, centred: pixel centres map to view directions as in BrdfMap. The light's
     * uniforms are those of the settings the material was built for (a preview's program declares its own method's
     * uniforms, not the configured one's).
     */
    private void showBrdfMap(ViewerState state, BrdfSettings settings, Material material, int widthPx, int heightPx) {
        int size = Math.max(1, Math.min(widthPx, heightPx));
        DiffractionMaterials.setLight(material, state.view().light().direction(), settings)
                .setFloat("mapSizePx", size)
                .setVec2("mapOriginPx", (widthPx - size) / 2, (heightPx - size) / 2);
        mapQuad.setMaterial(material);
        setRoot(mapScene);
    }

    @Override
    public void dispose(GLAutoDrawable drawable) {
        if (context() != null) {
            materials.releaseAll(context());
            if (pigmentationTexture != null) {
                context().release(pigmentationTexture);
            }
            if (stage != null) {
                stage.release(context());
            }
        }
        super.dispose(drawable);
    }
}
