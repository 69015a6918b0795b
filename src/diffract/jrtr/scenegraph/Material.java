package diffract.jrtr.scenegraph;

import com.jogamp.opengl.GL2ES2;
import com.jogamp.opengl.GL3;
import diffract.jrtr.shaders.UniformValue;
import diffract.jrtr.textures.Texture;

import javax.vecmath.Matrix4f;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;

/**
 * How a shape looks: a shader program, named textures and named uniform values. Texture units are assigned
 * automatically in the order textures were added (first texture on unit 0) and the sampler uniform of that
 * name is pointed at the unit. Textures are uploaded the first time the material is used.
 *
 * <p>The first draw checks the names both ways: a name the program's sources do not declare is a mistake (an
 * {@link IllegalArgumentException}), and so is a uniform the linked program uses that neither the material nor the
 * engine ({@link RenderContext#ENGINE_UNIFORMS}) sets, which would silently read 0 (an {@link IllegalStateException}).
 * A declared uniform the driver removed as unused may be set; the value is skipped.
 */
public final class Material {
    private final ShaderProgram program;
    private final Map<String, UniformValue> uniforms = new LinkedHashMap<>();
    private final Map<String, Texture> textures = new LinkedHashMap<>();
    private boolean namesChecked;

    public Material(ShaderProgram program) {
        this.program = program;
    }

    public ShaderProgram program() {
        return program;
    }

    public Material setFloat(String name, float value) {
        return set(name, new UniformValue.FloatValue(value));
    }

    public Material setInt(String name, int value) {
        return set(name, new UniformValue.IntValue(value));
    }

    public Material setVec2(String name, float x, float y) {
        return set(name, new UniformValue.VectorValue(new float[] {x, y}));
    }

    public Material setVec3(String name, float x, float y, float z) {
        return set(name, new UniformValue.VectorValue(new float[] {x, y, z}));
    }

    public Material setVec4(String name, float x, float y, float z, float w) {
        return set(name, new UniformValue.VectorValue(new float[] {x, y, z, w}));
    }

    public Material setMatrix(String name, Matrix4f matrix) {
        return set(name, new UniformValue.MatrixValue(matrix));
    }

    public Material setFloatArray(String name, float[] values) {
        return set(name, new UniformValue.FloatArrayValue(values));
    }

    /** Sets (or replaces) a uniform value; takes effect at the next draw. */
    public Material set(String name, UniformValue value) {
        if (textures.containsKey(name)) {
            throw new IllegalArgumentException(name + " is already a texture of this material");
        }
        uniforms.put(name, value);
        return this;
    }

    /** Binds a texture to the sampler uniform {@code samplerName}. */
    public Material setTexture(String samplerName, Texture texture) {
        if (uniforms.containsKey(samplerName)) {
            throw new IllegalArgumentException(samplerName + " is already a uniform value of this material");
        }
        textures.put(samplerName, texture);
        return this;
    }

    public Map<String, UniformValue> uniforms() {
        return Collections.unmodifiableMap(uniforms);
    }

    public Map<String, Texture> textures() {
        return Collections.unmodifiableMap(textures);
    }

    /**
     * Makes the program current (compiling it on first use), uploads textures on first use, binds them to
     * their units and sets all uniforms.
     */
    public void apply(GL3 gl) {
        program.use(gl);
        if (!namesChecked) {
            checkNames();
            namesChecked = true;
        }
        int[] maxUnits = new int[1];
        if (textures.size() > 16) {
            gl.glGetIntegerv(GL2ES2.GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, maxUnits, 0);
            if (textures.size() > maxUnits[0]) {
                throw new IllegalStateException(textures.size() + " textures exceed the " + maxUnits[0]
                        + " texture units of this GPU");
            }
        }
        // all uploads first: an upload binds its texture on unit 0 and unbinds it there afterwards, which would
        // undo the binding of a texture of the same target already bound to unit 0 for this draw
        for (Texture texture : textures.values()) {
            texture.upload(gl);
        }
        int unit = 0;
        for (Map.Entry<String, Texture> entry : textures.entrySet()) {
            entry.getValue().bind(gl, unit);
            int location = program.uniformLocation(gl, entry.getKey());
            if (location >= 0) {
                gl.glUniform1i(location, unit);
            }
            unit++;
        }
        for (Map.Entry<String, UniformValue> entry : uniforms.entrySet()) {
            int location = program.uniformLocation(gl, entry.getKey());
            if (location >= 0) {
                entry.getValue().apply(gl, location);
            }
        }
    }

    /** Every name set is declared, and every uniform the program uses is set (by this material or the engine). */
    private void checkNames() {
        Set<String> set = new LinkedHashSet<>(uniforms.keySet());
        set.addAll(textures.keySet());
        for (String name : set) {
            if (!program.declaredUniforms().contains(name)) {
                throw new IllegalArgumentException("the material sets '" + name + "', which " + program.name()
                        + " does not declare");
            }
        }
        for (String active : program.activeUniforms()) {
            if (!set.contains(active) && !RenderContext.ENGINE_UNIFORMS.contains(active)) {
                throw new IllegalStateException("uniform '" + active + "' of " + program.name()
                        + " is used but never set (it would read 0)");
            }
        }
    }
}
