package diffract.jrtr;

import com.jogamp.opengl.GL;
import com.jogamp.opengl.GL2ES2;
import com.jogamp.opengl.GL2ES3;
import com.jogamp.opengl.GL3;

import javax.vecmath.Matrix4f;
import javax.vecmath.Vector3f;
import java.util.Map;

/**
 * A shadow map for a directional light (L. Williams, "Casting Curved Shadows on Curved Surfaces", SIGGRAPH 1978):
 * the depth of the scene seen from the light through an orthographic box around a bounding sphere, kept in a
 * depth texture of raw depths that materials read with {@code texelFetch} and compare themselves (a light of
 * finite size needs the blockers' depths, not only the comparison: {@code lighting/environment.glsl}).
 * {@link #lightMatrix()} maps world points to the map's [0, 1]^3 (s, t, depth); {@link #texelWorld()} and
 * {@link #depthRangeWorld()} turn texels and depths back into world units. The depth pass uses its own tiny program
 * ({@code engine/shadow_depth.*}) and a slope-scaled polygon offset against self-shadowing; it leaves the framebuffer
 * binding and viewport as it found them.
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

    public ShadowMap(int sizePx) {
        if (sizePx < 16 || sizePx > 8192) {
            throw new IllegalArgumentException("shadow map size must be 16..8192, got " + sizePx);
        }
        this.sizePx = sizePx;
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

    @Override
    protected void fill(GL3 gl) {
        gl.glTexImage2D(GL.GL_TEXTURE_2D, 0, GL2ES3.GL_DEPTH_COMPONENT32F, sizePx, sizePx, 0,
                GL2ES2.GL_DEPTH_COMPONENT, GL.GL_FLOAT, null);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MIN_FILTER, GL.GL_NEAREST);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MAG_FILTER, GL.GL_NEAREST);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_WRAP_S, GL3.GL_CLAMP_TO_BORDER);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_WRAP_T, GL3.GL_CLAMP_TO_BORDER);
        gl.glTexParameterfv(GL.GL_TEXTURE_2D, GL3.GL_TEXTURE_BORDER_COLOR, new float[] {1, 1, 1, 1}, 0);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL2ES2.GL_TEXTURE_COMPARE_MODE, GL.GL_NONE);
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

    /** Renders the depth of every shape of {@code list} from the light (shapes' model matrices apply). */
    public void render(GLRenderContext context, RenderList list) {
        GL3 gl = context.gl();
        upload(gl);
        if (framebuffer == 0) {
            createFramebuffer(gl);
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
    }

    @Override
    public String toString() {
        return "ShadowMap[" + sizePx + "]";
    }
}
