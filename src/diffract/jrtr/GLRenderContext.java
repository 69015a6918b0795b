package diffract.jrtr;

import com.jogamp.common.util.VersionNumber;
import com.jogamp.opengl.GL3;
import com.jogamp.opengl.GL;
import diffract.jrtr.contexts.GLInfo;
import diffract.jrtr.gl.GLErrors;
import diffract.jrtr.gl.GLVersionException;
import diffract.jrtr.gl.GpuResource;
import diffract.jrtr.gl.PixelRect;
import diffract.jrtr.scenegraph.Camera;
import diffract.jrtr.scenegraph.DirectionalLight;
import diffract.jrtr.scenegraph.Frustum;
import diffract.jrtr.scenegraph.Material;
import diffract.jrtr.scenegraph.RenderContext;
import diffract.jrtr.scenegraph.RenderItem;
import diffract.jrtr.scenegraph.RenderList;
import diffract.jrtr.scenegraph.ShaderProgram;
import diffract.jrtr.scenegraph.Shape;
import diffract.jrtr.shaders.UniformValue;

import javax.vecmath.Matrix3f;
import javax.vecmath.Matrix4f;
import javax.vecmath.Point3f;
import java.util.IdentityHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/** The JOGL {@link RenderContext}: OpenGL 3.3 core or newer. */
public final class GLRenderContext implements RenderContext {
    /** The oldest OpenGL the engine runs on: VAOs, GLSL 3.30, texelFetch, float textures, timer queries. */
    public static final VersionNumber REQUIRED_VERSION = new VersionNumber(3, 3, 0);

    private final GL3 gl;
    private final GLInfo info;
    private final Map<Shape, GLMesh> meshes = new IdentityHashMap<>();
    private final Set<GpuResource> resources = new LinkedHashSet<>();
    private final ShaderProgram prepassProgram = ShaderProgram.fromClasspath("engine/depth_prepass.vert",
            "engine/shadow_depth.frag", Map.of());
    private boolean depthPrepass = true;
    private boolean disposed;

    /**
     * Wraps the current context's GL and reports its {@link GLInfo} ({@link GLInfo#reportTo}); throws {@link GLVersionException} naming the version found when it is
     * older than 3.3 or not a GL3-capable (core or compatible) context.
     */
    public GLRenderContext(GL gl) {
        requireVersion(gl);
        this.gl = gl.getGL3();
        this.info = GLInfo.of(gl);
        GLInfo.report(info);
        this.gl.glEnable(GL.GL_DEPTH_TEST);
        this.gl.glDepthFunc(GL.GL_LESS);
    }

    /** Throws {@link GLVersionException} unless {@code gl} is an OpenGL 3.3+ context usable as GL3. */
    public static void requireVersion(GL gl) {
        String version = gl.glGetString(GL.GL_VERSION);
        VersionNumber found;
        if (gl.getContext() != null) {
            found = gl.getContext().getGLVersionNumber();
        } else {
            int[] v = GLInfo.parseVersion(version);
            found = new VersionNumber(v[0], v[1], 0);
        }
        requireVersion(found, gl.isGL3(), version + ", " + gl.glGetString(GL.GL_RENDERER));
    }

    /**
     * The version rule on its own: {@code found} must be at least 3.3 and the context usable through the GL3
     * interface; {@code description} (driver version and renderer strings) goes into the message.
     */
    static void requireVersion(VersionNumber found, boolean usableAsGL3, String description) {
        if (found.compareTo(REQUIRED_VERSION) < 0 || !usableAsGL3) {
            throw new GLVersionException("OpenGL " + REQUIRED_VERSION.getMajor() + "." + REQUIRED_VERSION.getMinor()
                    + " core or newer required, found OpenGL " + found.getMajor() + "." + found.getMinor()
                    + (usableAsGL3 ? "" : " without GL3 core functions") + " (" + description + ")");
        }
    }

    /** The GL3 view of the wrapped context, for code that issues its own GL calls. */
    public GL3 gl() {
        return gl;
    }

    @Override
    public GLInfo info() {
        return info;
    }

    @Override
    public void setViewport(int x, int y, int width, int height) {
        gl.glViewport(x, y, width, height);
    }

    @Override
    public void setScissor(PixelRect rect) {
        if (rect == null) {
            gl.glDisable(GL.GL_SCISSOR_TEST);
        } else {
            gl.glEnable(GL.GL_SCISSOR_TEST);
            gl.glScissor(rect.x(), rect.y(), rect.width(), rect.height());
        }
    }

    @Override
    public void clear(float red, float green, float blue, float alpha) {
        gl.glClearColor(red, green, blue, alpha);
        gl.glClearDepth(1.0);
        gl.glDepthMask(true);
        gl.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT);
    }

    /**
     * Whether {@link #draw} first lays down the depths of the shapes whose programs match the pre-pass (on unless
     * switched off). A shape hidden behind another then costs its vertices only, not its fragment shader: on a
     * software rasteriser, where the fragments are the frame, a coiled snake over its ground shades each pixel once
     * instead of once per surface behind it.
     */
    public void setDepthPrepass(boolean on) {
        depthPrepass = on;
    }

    /**
     * Draws every item with its material. With the depth pre-pass on, the items whose programs compute their
     * positions as the pre-pass does ({@link ShaderProgram#matchesDepthPrepass}) have their depths laid down first
     * and are then shaded where their depth equals the nearest one (GL_LEQUAL, depth writes off); other items are
     * drawn as without it (GL_LESS, depth writes on), so a program that places its vertices another way (a
     * full-screen quad) is never hidden by a depth it did not write.
     */
    @Override
    public void draw(RenderList list, Camera camera, Frustum frustum) {
        requireAlive();
        gl.glEnable(GL.GL_DEPTH_TEST);
        Matrix4f view = camera.viewMatrix();
        Matrix4f projection = frustum.projectionMatrix();
        List<RenderItem> prepassed = depthPrepass
                ? list.items().stream().filter(GLRenderContext::matchesPrepass).toList() : List.of();
        if (!prepassed.isEmpty()) {
            gl.glColorMask(false, false, false, false);
            gl.glDepthFunc(GL.GL_LESS);
            gl.glDepthMask(true);
            drawDepthOnly(prepassed, prepassProgram, view, projection);
            gl.glColorMask(true, true, true, true);
        }
        List<DirectionalLight> lights = list.lights();
        if (lights.size() > MAX_LIGHTS) {
            throw new IllegalStateException(lights.size() + " lights; the engine passes at most " + MAX_LIGHTS);
        }
        float[] lightDirections = new float[Math.max(1, lights.size()) * 3];
        float[] lightRadiances = new float[Math.max(1, lights.size()) * 3];
        for (int i = 0; i < lights.size(); i++) {
            putVector(lightDirections, i, lights.get(i).direction());
            putVector(lightRadiances, i, lights.get(i).radiance());
        }
        Point3f eye = camera.eye();
        for (RenderItem item : list.items()) {
            Material material = item.material();
            if (material == null) {
                throw new IllegalStateException(item.node() + " has no material");
            }
            boolean afterPrepass = depthPrepass && matchesPrepass(item);
            gl.glDepthFunc(afterPrepass ? GL.GL_LEQUAL : GL.GL_LESS);
            gl.glDepthMask(!afterPrepass);
            ShaderProgram program = material.program();
            program.use(gl);
            resources.add(program);
            Matrix4f model = item.modelMatrix();
            setMatrix(program, "model", model);
            setMatrix(program, "view", view);
            setMatrix(program, "projection", projection);
            int location = program.uniformLocation(gl, "normalMatrix");
            if (location >= 0) {
                gl.glUniformMatrix3fv(location, 1, false, normalMatrixColumnMajor(model), 0);
            }
            location = program.uniformLocation(gl, "cameraPosition");
            if (location >= 0) {
                gl.glUniform3f(location, eye.x, eye.y, eye.z);
            }
            location = program.uniformLocation(gl, "lightCount");
            if (location >= 0) {
                gl.glUniform1i(location, lights.size());
            }
            location = program.uniformLocation(gl, "lightDirection");
            if (location >= 0 && !lights.isEmpty()) {
                gl.glUniform3fv(location, lights.size(), lightDirections, 0);
            }
            location = program.uniformLocation(gl, "lightRadiance");
            if (location >= 0 && !lights.isEmpty()) {
                gl.glUniform3fv(location, lights.size(), lightRadiances, 0);
            }
            material.apply(gl);
            resources.addAll(material.textures().values());
            meshes.computeIfAbsent(item.shape(), shape -> GLMesh.upload(gl, shape.vertexData())).draw(gl);
            GLErrors.check(gl, "drawing " + item.node() + " with " + program);
        }
        gl.glDepthFunc(GL.GL_LESS);
        gl.glDepthMask(true);
    }

    private static boolean matchesPrepass(RenderItem item) {
        return item.material() != null && item.material().program().matchesDepthPrepass();
    }

    /**
     * Draws every shape of {@code list} with {@code program} alone (no material uniforms or textures), through the
     * given view and projection, with depth testing: for depth-only passes such as {@link ShadowMap}'s.
     */
    public void drawDepthOnly(RenderList list, ShaderProgram program, Matrix4f view, Matrix4f projection) {
        drawDepthOnly(list.items(), program, view, projection);
    }

    private void drawDepthOnly(List<RenderItem> items, ShaderProgram program, Matrix4f view, Matrix4f projection) {
        requireAlive();
        gl.glEnable(GL.GL_DEPTH_TEST);
        program.use(gl);
        resources.add(program);
        for (RenderItem item : items) {
            setMatrix(program, "model", item.modelMatrix());
            setMatrix(program, "view", view);
            setMatrix(program, "projection", projection);
            meshes.computeIfAbsent(item.shape(), shape -> GLMesh.upload(gl, shape.vertexData())).draw(gl);
        }
        GLErrors.check(gl, "drawing depth with " + program);
    }

    private static void putVector(float[] array, int index, javax.vecmath.Tuple3f value) {
        array[index * 3] = value.x;
        array[index * 3 + 1] = value.y;
        array[index * 3 + 2] = value.z;
    }

    private void setMatrix(ShaderProgram program, String name, Matrix4f matrix) {
        int location = program.uniformLocation(gl, name);
        if (location >= 0) {
            gl.glUniformMatrix4fv(location, 1, false, UniformValue.columnMajor(matrix), 0);
        }
    }

    /** Normals transform with the inverse transpose, so non-uniform scaling keeps them perpendicular. */
    static float[] normalMatrixColumnMajor(Matrix4f model) {
        Matrix3f m = new Matrix3f();
        model.getRotationScale(m);
        if (Math.abs(m.determinant()) > 1e-12f) {
            m.invert();
            m.transpose();
        }
        // column-major of m: column j holds m.m0j, m.m1j, m.m2j
        return new float[] {m.m00, m.m10, m.m20, m.m01, m.m11, m.m21, m.m02, m.m12, m.m22};
    }

    /** Uploads a shape's geometry now instead of at its first draw (e.g. to keep the first frame short). */
    public void upload(Shape shape) {
        requireAlive();
        meshes.computeIfAbsent(shape, s -> GLMesh.upload(gl, s.vertexData()));
    }

    /**
     * Frees a program or texture this context uploaded and forgets it, for callers that replace materials while
     * the context lives (an interactive viewer switching shaders): without this the context would keep every
     * replaced resource, and its CPU data, until {@link #dispose()}.
     */
    public void release(GpuResource resource) {
        requireAlive();
        resource.dispose(gl);
        resources.remove(resource);
    }

    /** Number of shapes whose geometry is on the GPU: each shape is uploaded once however often it is drawn. */
    public int uploadedShapeCount() {
        return meshes.size();
    }

    @Override
    public void dispose() {
        if (disposed) {
            return;
        }
        for (GLMesh mesh : meshes.values()) {
            mesh.delete(gl);
        }
        meshes.clear();
        for (GpuResource resource : resources) {
            resource.dispose(gl);
        }
        resources.clear();
        disposed = true;
    }

    private void requireAlive() {
        if (disposed) {
            throw new IllegalStateException("render context already disposed");
        }
    }
}
