package diffract.jrtr.shaders;

import com.jogamp.opengl.GL2ES2;
import com.jogamp.opengl.GL3;

import java.nio.charset.StandardCharsets;

/** One preprocessed shader stage; compiling it reports errors in original file:line terms. */
public final class Shader {
    private final ShaderStage stage;
    private final PreprocessedSource source;

    public Shader(ShaderStage stage, PreprocessedSource source) {
        this.stage = stage;
        this.source = source;
    }

    public ShaderStage stage() {
        return stage;
    }

    public PreprocessedSource source() {
        return source;
    }

    /** Compiles into a new GL shader object and returns its name; throws {@link ShaderException} on errors. */
    public int compile(GL3 gl) {
        int id = gl.glCreateShader(stage.glType());
        if (id == 0) {
            throw new IllegalStateException("glCreateShader failed for " + source.path());
        }
        gl.glShaderSource(id, 1, new String[] {source.text()}, null, 0);
        gl.glCompileShader(id);
        int[] status = new int[1];
        gl.glGetShaderiv(id, GL2ES2.GL_COMPILE_STATUS, status, 0);
        if (status[0] == 0) {
            String log = shaderLog(gl, id);
            gl.glDeleteShader(id);
            throw new ShaderException("cannot compile " + stage + " shader " + source.path() + ":",
                    ShaderLogTranslator.translate(log, source.sourceMap()));
        }
        return id;
    }

    static String shaderLog(GL3 gl, int shader) {
        int[] length = new int[1];
        gl.glGetShaderiv(shader, GL2ES2.GL_INFO_LOG_LENGTH, length, 0);
        if (length[0] <= 1) {
            return "";
        }
        byte[] bytes = new byte[length[0]];
        gl.glGetShaderInfoLog(shader, bytes.length, length, 0, bytes, 0);
        return new String(bytes, 0, length[0], StandardCharsets.UTF_8);
    }

    @Override
    public String toString() {
        return stage + " shader " + source.path();
    }
}
