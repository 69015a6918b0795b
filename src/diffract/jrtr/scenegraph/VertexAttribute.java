package diffract.jrtr.scenegraph;

/**
 * The vertex attributes the engine knows. Every shader program binds these names to the same fixed locations
 * before linking ({@code glBindAttribLocation}), so one vertex array object per shape works with every program,
 * and a shader simply declares {@code in vec3 position;} etc. for the attributes it uses.
 */
public enum VertexAttribute {
    POSITION("position", 3),
    NORMAL("normal", 3),
    TANGENT("tangent", 3),
    TEXCOORD("texcoord", 2);

    private final String glslName;
    private final int components;

    VertexAttribute(String glslName, int components) {
        this.glslName = glslName;
        this.components = components;
    }

    /** The {@code in} variable name a vertex shader uses for this attribute. */
    public String glslName() {
        return glslName;
    }

    /** Floats per vertex. */
    public int components() {
        return components;
    }

    /** The attribute location every program binds this attribute to. */
    public int location() {
        return ordinal();
    }
}
