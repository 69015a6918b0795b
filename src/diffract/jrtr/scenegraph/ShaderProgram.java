package diffract.jrtr.scenegraph;

import com.jogamp.opengl.GL2ES2;
import com.jogamp.opengl.GL3;
import diffract.jrtr.gl.GLErrors;
import diffract.jrtr.gl.GpuResource;
import diffract.jrtr.shaders.GlslPreprocessor;
import diffract.jrtr.shaders.Shader;
import diffract.jrtr.shaders.ShaderException;
import diffract.jrtr.shaders.ShaderSourceRoot;
import diffract.jrtr.shaders.ShaderStage;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A vertex + fragment program. Sources are read and preprocessed when the object is made (so missing files and
 * bad includes fail early, without GL); the GL program is compiled and linked on first use in a context. The
 * engine's vertex attributes ({@link VertexAttribute}) are bound to fixed locations by name before linking.
 * Uniform locations are looked up once per name and cached. The program knows the uniforms its sources declare
 * (whatever {@code #ifdef}s say) and, once linked, those the driver kept active: {@link Material} checks both.
 */
public final class ShaderProgram extends GpuResource {
    /** {@code uniform TYPE NAME} (arrays with their size), as GLSL 3.30 declares uniforms outside blocks. */
    private static final Pattern UNIFORM = Pattern.compile("\\buniform\\s+\\w+\\s+(\\w+)");

    private final String name;
    private final Shader vertex;
    private final Shader fragment;
    private final Set<String> declaredUniforms;
    /** Read once from the source: every frame asks it of every item drawn. */
    private final boolean matchesDepthPrepass;
    private final Map<String, Integer> uniformLocations = new HashMap<>();
    private Set<String> activeUniforms = Set.of();
    private int program;

    public ShaderProgram(Shader vertex, Shader fragment) {
        if (vertex.stage() != ShaderStage.VERTEX || fragment.stage() != ShaderStage.FRAGMENT) {
            throw new IllegalArgumentException("need a vertex and a fragment shader, got " + vertex + ", " + fragment);
        }
        this.vertex = vertex;
        this.fragment = fragment;
        this.name = vertex.source().path() + " + " + fragment.source().path();
        Set<String> declared = new LinkedHashSet<>();
        for (Shader shader : List.of(vertex, fragment)) {
            Matcher m = UNIFORM.matcher(shader.source().text());
            while (m.find()) {
                declared.add(m.group(1));
            }
        }
        this.declaredUniforms = Collections.unmodifiableSet(declared);
        this.matchesDepthPrepass = INVARIANT_POSITION.matcher(vertex.source().text()).find();
    }

    /** The engine's own defines, in every program: the size of its light arrays ({@link RenderContext#MAX_LIGHTS}). */
    public static final String MAX_LIGHTS_DEFINE = "ENGINE_MAX_LIGHTS";

    /** Loads both stages from {@code root} with the same {@code defines} and the engine's ({@link #MAX_LIGHTS_DEFINE}). */
    public static ShaderProgram load(ShaderSourceRoot root, String vertexPath, String fragmentPath,
                                     Map<String, String> defines) {
        GlslPreprocessor preprocessor = new GlslPreprocessor(root);
        Map<String, String> all = new java.util.TreeMap<>(defines);
        all.put(MAX_LIGHTS_DEFINE, Integer.toString(RenderContext.MAX_LIGHTS));
        return new ShaderProgram(
                new Shader(ShaderStage.VERTEX, preprocessor.process(vertexPath, all)),
                new Shader(ShaderStage.FRAGMENT, preprocessor.process(fragmentPath, all)));
    }

    /** Loads from the classpath folder {@code /shaders}, e.g. {@code fromClasspath("engine/unlit.vert", ...)}. */
    public static ShaderProgram fromClasspath(String vertexPath, String fragmentPath, Map<String, String> defines) {
        return load(ShaderSourceRoot.classpath(), vertexPath, fragmentPath, defines);
    }

    /** Loads from files under {@code directory}. */
    public static ShaderProgram fromDirectory(Path directory, String vertexPath, String fragmentPath,
                                              Map<String, String> defines) {
        return load(ShaderSourceRoot.directory(directory), vertexPath, fragmentPath, defines);
    }

    public String name() {
        return name;
    }

    public Shader vertexShader() {
        return vertex;
    }

    public Shader fragmentShader() {
        return fragment;
    }

    /**
     * Whether the vertex stage declares {@code invariant gl_Position} and so computes its positions as the depth
     * pre-pass does ({@code engine/depth_prepass.vert}: {@code projection * view * (model * position)}): only such
     * programs may be drawn against the pre-pass's depths with an equal-passes test.
     */
    public boolean matchesDepthPrepass() {
        return matchesDepthPrepass;
    }

    private static final Pattern INVARIANT_POSITION = Pattern.compile("(?m)^\\s*invariant\\s+gl_Position\\s*;");

    /** The uniforms the sources declare, in any branch of their {@code #ifdef}s. */
    public Set<String> declaredUniforms() {
        return declaredUniforms;
    }

    /** The uniforms the linked program uses (array uniforms by their name, without "[0]"); empty before linking. */
    public Set<String> activeUniforms() {
        return activeUniforms;
    }

    /** The GL program name; the program must have been uploaded. */
    public int glProgram() {
        requireUploaded();
        return program;
    }

    /** Compiles and links if needed, then makes this the current program. */
    public void use(GL3 gl) {
        upload(gl);
        gl.glUseProgram(program);
    }

    /**
     * Location of a uniform (for arrays, of element 0), or -1 when the program has no such active uniform —
     * drivers drop uniforms the shader does not use, and setting those is silently skipped.
     */
    public int uniformLocation(GL3 gl, String uniform) {
        requireUploaded();
        return uniformLocations.computeIfAbsent(uniform, u -> gl.glGetUniformLocation(program, u));
    }

    @Override
    protected void createOnGpu(GL3 gl) {
        int vertexShader = vertex.compile(gl);
        int fragmentShader;
        try {
            fragmentShader = fragment.compile(gl);
        } catch (RuntimeException e) {
            gl.glDeleteShader(vertexShader);
            throw e;
        }
        int id = gl.glCreateProgram();
        gl.glAttachShader(id, vertexShader);
        gl.glAttachShader(id, fragmentShader);
        for (VertexAttribute attribute : VertexAttribute.values()) {
            gl.glBindAttribLocation(id, attribute.location(), attribute.glslName());
        }
        gl.glBindFragDataLocation(id, 0, "fragColor");
        gl.glLinkProgram(id);
        // shader objects are only needed for linking; flagging them now frees them with the program
        gl.glDetachShader(id, vertexShader);
        gl.glDetachShader(id, fragmentShader);
        gl.glDeleteShader(vertexShader);
        gl.glDeleteShader(fragmentShader);
        int[] status = new int[1];
        gl.glGetProgramiv(id, GL2ES2.GL_LINK_STATUS, status, 0);
        if (status[0] == 0) {
            String log = programLog(gl, id);
            gl.glDeleteProgram(id);
            throw new ShaderException("cannot link " + name + ":", List.of(log.trim().split("\r?\n")));
        }
        program = id;
        uniformLocations.clear();
        activeUniforms = activeUniforms(gl, id);
        GLErrors.check(gl, "after linking " + name);
    }

    @Override
    protected void deleteOnGpu(GL3 gl) {
        gl.glDeleteProgram(program);
        program = 0;
        uniformLocations.clear();
    }

    /** GL 4.2's type of an {@code atomic_uint} uniform (GL_UNSIGNED_INT_ATOMIC_COUNTER). */
    private static final int UNSIGNED_INT_ATOMIC_COUNTER = 0x92DB;

    private static Set<String> activeUniforms(GL3 gl, int id) {
        int[] count = new int[1];
        gl.glGetProgramiv(id, GL2ES2.GL_ACTIVE_UNIFORMS, count, 0);
        int[] maxLength = new int[1];
        gl.glGetProgramiv(id, GL2ES2.GL_ACTIVE_UNIFORM_MAX_LENGTH, maxLength, 0);
        Set<String> names = new LinkedHashSet<>();
        byte[] buffer = new byte[Math.max(1, maxLength[0])];
        int[] length = new int[1];
        int[] size = new int[1];
        int[] type = new int[1];
        for (int i = 0; i < count[0]; i++) {
            gl.glGetActiveUniform(id, i, buffer.length, length, 0, size, 0, type, 0, buffer, 0);
            String uniform = new String(buffer, 0, length[0], StandardCharsets.UTF_8);
            if (type[0] == UNSIGNED_INT_ATOMIC_COUNTER) {
                continue; // a buffer's, bound by its binding point: no value a material sets
            }
            names.add(uniform.endsWith("[0]") ? uniform.substring(0, uniform.length() - 3) : uniform);
        }
        return Collections.unmodifiableSet(names);
    }

    private void requireUploaded() {
        if (!isUploaded()) {
            throw new IllegalStateException(name + " is not compiled yet; call use(gl) or upload(gl) first");
        }
    }

    private static String programLog(GL3 gl, int id) {
        int[] length = new int[1];
        gl.glGetProgramiv(id, GL2ES2.GL_INFO_LOG_LENGTH, length, 0);
        if (length[0] <= 1) {
            return "(no log)";
        }
        byte[] bytes = new byte[length[0]];
        gl.glGetProgramInfoLog(id, bytes.length, length, 0, bytes, 0);
        return new String(bytes, 0, length[0], StandardCharsets.UTF_8);
    }

    @Override
    public String toString() {
        return "ShaderProgram[" + name + "]";
    }
}
