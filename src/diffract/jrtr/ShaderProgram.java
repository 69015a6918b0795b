package diffract.jrtr;

import com.jogamp.opengl.GL2ES2;
import com.jogamp.opengl.GL3;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * A vertex + fragment program. Sources are read and preprocessed when the object is made (so missing files and
 * bad includes fail early, without GL); the GL program is compiled and linked on first use in a context. The
 * engine's vertex attributes ({@link VertexAttribute}) are bound to fixed locations by name before linking.
 * Uniform locations are looked up once per name and cached.
 */
public final class ShaderProgram extends GpuResource {
    private final String name;
    private final Shader vertex;
    private final Shader fragment;
    private final Map<String, Integer> uniformLocations = new HashMap<>();
    private int program;

    public ShaderProgram(Shader vertex, Shader fragment) {
        if (vertex.stage() != ShaderStage.VERTEX || fragment.stage() != ShaderStage.FRAGMENT) {
            throw new IllegalArgumentException("need a vertex and a fragment shader, got " + vertex + ", " + fragment);
        }
        this.vertex = vertex;
        this.fragment = fragment;
        this.name = vertex.source().path() + " + " + fragment.source().path();
    }

    /** Loads both stages from {@code root} with the same {@code defines}. */
    public static ShaderProgram load(ShaderSourceRoot root, String vertexPath, String fragmentPath,
                                     Map<String, String> defines) {
        GlslPreprocessor preprocessor = new GlslPreprocessor(root);
        return new ShaderProgram(
                new Shader(ShaderStage.VERTEX, preprocessor.process(vertexPath, defines)),
                new Shader(ShaderStage.FRAGMENT, preprocessor.process(fragmentPath, defines)));
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
        GLErrors.check(gl, "after linking " + name);
    }

    @Override
    protected void deleteOnGpu(GL3 gl) {
        gl.glDeleteProgram(program);
        program = 0;
        uniformLocations.clear();
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
