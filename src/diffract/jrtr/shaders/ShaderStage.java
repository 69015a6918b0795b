package diffract.jrtr.shaders;

import com.jogamp.opengl.GL2ES2;

/** The programmable stages the engine uses. */
public enum ShaderStage {
    VERTEX(GL2ES2.GL_VERTEX_SHADER, "vertex"),
    FRAGMENT(GL2ES2.GL_FRAGMENT_SHADER, "fragment");

    private final int glType;
    private final String label;

    ShaderStage(int glType, String label) {
        this.glType = glType;
        this.label = label;
    }

    public int glType() {
        return glType;
    }

    @Override
    public String toString() {
        return label;
    }
}
