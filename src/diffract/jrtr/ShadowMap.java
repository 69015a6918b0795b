package diffract.jrtr;

import com.jogamp.opengl.GL2ES2;
import com.jogamp.opengl.GL2ES3;
import com.jogamp.opengl.GL3;
import com.jogamp.opengl.GL;
import diffract.jrtr.gl.GLErrors;
import diffract.jrtr.scenegraph.RenderItem;
import diffract.jrtr.scenegraph.RenderList;
import diffract.jrtr.scenegraph.ShaderProgram;
import diffract.jrtr.textures.DepthBounds;
import diffract.jrtr.textures.Texture;

import javax.vecmath.Matrix4f;
import javax.vecmath.Vector3f;
import java.nio.FloatBuffer;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * A shadow map for a directional light (L. Williams, "Casting Curved Shadows on Curved Surfaces", SIGGRAPH 1978):
 * the depth of the scene seen from the light through an orthographic box around a bounding sphere, kept in a
 * depth texture that materials sample with comparisons ({@code sampler2DShadow}, bilinear), and the same depths raw in
 * level 0 of its {@link DepthBounds} (a light of finite size needs the blockers' depths, not only the comparison:
 * {@code lighting/environment.glsl}).
 * {@link #lightMatrix()} maps world points to the map's [0, 1]^3 (s, t, depth); {@link #texelWorld()} and
 * {@link #depthRangeWorld()} turn texels and depths back into world units. The depth pass uses its own tiny program
 * ({@code engine/shadow_depth.*}) and a slope-scaled polygon offset against self-shadowing; it leaves the framebuffer
 * binding and viewport as it found them. A map whose light, box and casters are those of its last pass is not drawn
 * again: a still scene's shadow costs its lookups only. After each pass the map's {@link DepthBounds} are rebuilt, so
 * that a lookup can settle a whole region of the map at once.
 */
public final class ShadowMap extends Texture {
    private final int sizePx;
    private int framebuffer;
    private final ShaderProgram depthProgram = ShaderProgram.fromClasspath("engine/shadow_depth.vert",
            "engine/shadow_depth.frag", Map.of());
    private final Matrix4f view = new Matrix4f();
    private final Matrix4f projection = new Matrix4f();
    private float boxHalfWidth = 1;
    private float depthRange = 1;
    private final DepthBounds bounds;
    /** What the map's content was drawn from (view, projection, casters' shapes and model matrices), or null. */
    private List<Object> drawnFrom;
    private int passes;

    /** @param sizePx side of the map, a power of two in 16..8192 */
    public ShadowMap(int sizePx) {
        if (sizePx < 16 || sizePx > 8192 || Integer.bitCount(sizePx) != 1) {
            throw new IllegalArgumentException("shadow map size must be a power of two in 16..8192, got " + sizePx);
        }
        this.sizePx = sizePx;
        this.bounds = new DepthBounds(sizePx);
        view.setIdentity();
        projection.setIdentity();
    }

    public int sizePx() {
        return sizePx;
    }

    @Override
    public int glTarget() {
        return GL.GL_TEXTURE_2D;
    }

    /** The bounds of the map's depths over blocks of texels, rebuilt by each {@link #render} that draws. */
    public DepthBounds depthBounds() {
        return bounds;
    }

    @Override
    protected void fill(GL3 gl) {
        drawnFrom = null; // a new texture object holds nothing yet
        depthImage(gl, sizePx, null);
    }

    /**
     * Allocates (or fills, given {@code depth}) the bound GL_TEXTURE_2D as a size^2 depth map sampled with
     * comparisons: a sampler2DShadow's lookup compares the four texels around a point (GL_LEQUAL: lit where the
     * receiver lies at or in front of the stored depth) and blends them bilinearly; beyond the map the border, depth
     * 1, blocks nothing. Raw depths come from {@link #depthBounds()}.
     */
    static void depthImage(GL3 gl, int size, float[] depth) {
        gl.glTexImage2D(GL.GL_TEXTURE_2D, 0, GL2ES3.GL_DEPTH_COMPONENT32F, size, size, 0,
                GL2ES2.GL_DEPTH_COMPONENT, GL.GL_FLOAT, depth == null ? null : FloatBuffer.wrap(depth));
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MIN_FILTER, GL.GL_LINEAR);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MAG_FILTER, GL.GL_LINEAR);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_WRAP_S, GL3.GL_CLAMP_TO_BORDER);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_WRAP_T, GL3.GL_CLAMP_TO_BORDER);
        gl.glTexParameterfv(GL.GL_TEXTURE_2D, GL3.GL_TEXTURE_BORDER_COLOR, new float[] {1, 1, 1, 1}, 0);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL2ES2.GL_TEXTURE_COMPARE_MODE, GL2ES2.GL_COMPARE_REF_TO_TEXTURE);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL2ES2.GL_TEXTURE_COMPARE_FUNC, GL.GL_LEQUAL);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL3.GL_TEXTURE_BASE_LEVEL, 0);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL3.GL_TEXTURE_MAX_LEVEL, 0);
    }

    /** The framebuffer with the depth texture attached, made after the texture is uploaded. */
    private void createFramebuffer(GL3 gl) {
        int[] fbo = new int[1];
        gl.glGenFramebuffers(1, fbo, 0);
        framebuffer = fbo[0];
        int[] previous = new int[1];
        gl.glGetIntegerv(GL2ES3.GL_DRAW_FRAMEBUFFER_BINDING, previous, 0);
        gl.glBindFramebuffer(GL.GL_FRAMEBUFFER, framebuffer);
        gl.glFramebufferTexture2D(GL.GL_FRAMEBUFFER, GL.GL_DEPTH_ATTACHMENT, GL.GL_TEXTURE_2D, glTexture(), 0);
        gl.glDrawBuffer(GL.GL_NONE);
        gl.glReadBuffer(GL.GL_NONE);
        int status = gl.glCheckFramebufferStatus(GL.GL_FRAMEBUFFER);
        gl.glBindFramebuffer(GL.GL_FRAMEBUFFER, previous[0]);
        if (status != GL.GL_FRAMEBUFFER_COMPLETE) {
            throw new IllegalStateException("shadow framebuffer incomplete: 0x" + Integer.toHexString(status));
        }
    }

    @Override
    protected void deleteOnGpu(GL3 gl) {
        if (framebuffer != 0) {
            gl.glDeleteFramebuffers(1, new int[] {framebuffer}, 0);
        }
        framebuffer = 0;
        depthProgram.dispose(gl);
        bounds.dispose(gl);
        drawnFrom = null;
        super.deleteOnGpu(gl);
    }

    /**
     * Aims the map: the light looks along -towardsLight at the sphere (centre, radius), which the orthographic box
     * encloses with a margin, widened by {@code penumbraPerDepth} (tan of half a light's angular diameter) times the
     * sphere's diameter: a penumbra reaches that far beyond the shadow of the sphere's edge.
     */
    public void aim(Vector3f towardsLight, Vector3f centre, float radius, float penumbraPerDepth) {
        Vector3f d = new Vector3f(towardsLight);
        d.normalize();
        Vector3f up = Math.abs(d.y) > 0.99f ? new Vector3f(1, 0, 0) : new Vector3f(0, 1, 0);
        Vector3f eye = new Vector3f(d);
        eye.scale(2 * radius);
        eye.add(centre);
        Vector3f z = new Vector3f(d); // camera looks along -z
        Vector3f x = new Vector3f();
        x.cross(up, z);
        x.normalize();
        Vector3f y = new Vector3f();
        y.cross(z, x);
        view.setIdentity();
        view.setRow(0, x.x, x.y, x.z, -x.dot(eye));
        view.setRow(1, y.x, y.y, y.z, -y.dot(eye));
        view.setRow(2, z.x, z.y, z.z, -z.dot(eye));
        float r = radius * (1.05f + 2 * Math.max(0, penumbraPerDepth));
        float near = radius * 0.5f;
        float far = radius * 3.5f;
        boxHalfWidth = r;
        depthRange = far - near;
        projection.setIdentity();
        projection.setRow(0, 1 / r, 0, 0, 0);
        projection.setRow(1, 0, 1 / r, 0, 0);
        projection.setRow(2, 0, 0, -2 / (far - near), -(far + near) / (far - near));
        projection.setRow(3, 0, 0, 0, 1);
    }

    /** World units across one texel of the map (after {@link #aim}). */
    public float texelWorld() {
        return 2 * boxHalfWidth / sizePx;
    }

    /** World units along the light per unit of stored depth (after {@link #aim}). */
    public float depthRangeWorld() {
        return depthRange;
    }

    /** World to the map's [0, 1]^3: bias x projection x view. */
    public Matrix4f lightMatrix() {
        Matrix4f bias = new Matrix4f(0.5f, 0, 0, 0.5f, 0, 0.5f, 0, 0.5f, 0, 0, 0.5f, 0.5f, 0, 0, 0, 1);
        Matrix4f m = new Matrix4f(bias);
        m.mul(projection);
        m.mul(view);
        return m;
    }

    /**
     * Renders the depth of every shape of {@code list} from the light (shapes' model matrices apply), unless the map
     * holds that already; then rebuilds the depth bounds.
     */
    public void render(GLRenderContext context, RenderList list) {
        GL3 gl = context.gl();
        upload(gl);
        bounds.upload(gl);
        if (framebuffer == 0) {
            createFramebuffer(gl);
        }
        List<Object> from = drawnFrom(list);
        if (from.equals(drawnFrom)) {
            return;
        }
        int[] previous = new int[1];
        gl.glGetIntegerv(GL2ES3.GL_DRAW_FRAMEBUFFER_BINDING, previous, 0);
        int[] viewport = new int[4];
        gl.glGetIntegerv(GL.GL_VIEWPORT, viewport, 0);
        gl.glBindFramebuffer(GL.GL_FRAMEBUFFER, framebuffer);
        gl.glViewport(0, 0, sizePx, sizePx);
        gl.glClearDepth(1.0);
        gl.glDepthMask(true);
        gl.glClear(GL.GL_DEPTH_BUFFER_BIT);
        gl.glEnable(GL.GL_POLYGON_OFFSET_FILL);
        gl.glPolygonOffset(2f, 4f);
        context.drawDepthOnly(list, depthProgram, view, projection);
        gl.glDisable(GL.GL_POLYGON_OFFSET_FILL);
        gl.glBindFramebuffer(GL.GL_FRAMEBUFFER, previous[0]);
        gl.glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
        GLErrors.check(gl, "rendering the shadow map");
        float[] depth = new float[sizePx * sizePx];
        gl.glActiveTexture(GL.GL_TEXTURE0);
        gl.glBindTexture(GL.GL_TEXTURE_2D, glTexture());
        gl.glPixelStorei(GL.GL_PACK_ALIGNMENT, 1);
        gl.glGetTexImage(GL.GL_TEXTURE_2D, 0, GL2ES2.GL_DEPTH_COMPONENT, GL.GL_FLOAT, FloatBuffer.wrap(depth));
        gl.glBindTexture(GL.GL_TEXTURE_2D, 0);
        GLErrors.check(gl, "reading the shadow map back");
        bounds.update(gl, depth);
        drawnFrom = from;
        passes++;
    }

    /** How many times {@link #render} has drawn the map (a still scene draws it once). */
    public int passes() {
        return passes;
    }

    /**
     * What a pass draws from: the light's view and projection, and per caster its shape (by identity: shapes are
     * immutable) and model matrix.
     */
    private List<Object> drawnFrom(RenderList list) {
        List<Object> from = new ArrayList<>();
        from.add(new Matrix4f(view));
        from.add(new Matrix4f(projection));
        for (RenderItem item : list.items()) {
            from.add(new IdentityKey(item.shape()));
            from.add(new Matrix4f(item.modelMatrix()));
        }
        return from;
    }

    /** Equal only to a key of the same object. */
    private record IdentityKey(Object of) {
        @Override
        public boolean equals(Object o) {
            return o instanceof IdentityKey k && k.of == of;
        }

        @Override
        public int hashCode() {
            return System.identityHashCode(of);
        }
    }

    @Override
    public String toString() {
        return "ShadowMap[" + sizePx + "]";
    }
}
