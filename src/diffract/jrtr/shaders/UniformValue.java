package diffract.jrtr.shaders;

import com.jogamp.opengl.GL3;

import javax.vecmath.Matrix4f;

/** A value for a named uniform; each kind knows the glUniform call that sets it. */
public sealed interface UniformValue {
    /** Sets the uniform at {@code location} of the current program. */
    void apply(GL3 gl, int location);

    /** A {@code float} uniform. */
    record FloatValue(float value) implements UniformValue {
        @Override
        public void apply(GL3 gl, int location) {
            gl.glUniform1f(location, value);
        }
    }

    /** An {@code int} (or sampler unit) uniform. */
    record IntValue(int value) implements UniformValue {
        @Override
        public void apply(GL3 gl, int location) {
            gl.glUniform1i(location, value);
        }
    }

    /** vec2, vec3 or vec4, by the number of components. */
    record VectorValue(float[] components) implements UniformValue {
        public VectorValue {
            if (components.length < 2 || components.length > 4) {
                throw new IllegalArgumentException("vectors have 2 to 4 components, got " + components.length);
            }
            components = components.clone();
        }

        @Override
        public void apply(GL3 gl, int location) {
            switch (components.length) {
                case 2 -> gl.glUniform2f(location, components[0], components[1]);
                case 3 -> gl.glUniform3f(location, components[0], components[1], components[2]);
                default -> gl.glUniform4f(location, components[0], components[1], components[2], components[3]);
            }
        }
    }

    /** A {@code float[]} uniform array; the shader's array may be longer (the rest keeps its values). */
    record FloatArrayValue(float[] values) implements UniformValue {
        public FloatArrayValue {
            if (values.length == 0) {
                throw new IllegalArgumentException("empty uniform array");
            }
            values = values.clone();
        }

        @Override
        public void apply(GL3 gl, int location) {
            gl.glUniform1fv(location, values.length, values, 0);
        }
    }

    /** A {@code vec3[]} uniform array, three floats per element; the shader's array may be longer. */
    record Vector3ArrayValue(float[] xyz) implements UniformValue {
        public Vector3ArrayValue {
            if (xyz.length == 0 || xyz.length % 3 != 0) {
                throw new IllegalArgumentException("a vec3 array needs a positive multiple of 3 floats, got " + xyz.length);
            }
            xyz = xyz.clone();
        }

        @Override
        public void apply(GL3 gl, int location) {
            gl.glUniform3fv(location, xyz.length / 3, xyz, 0);
        }
    }

    /** A {@code mat4} uniform. */
    record MatrixValue(Matrix4f matrix) implements UniformValue {
        public MatrixValue {
            matrix = new Matrix4f(matrix);
        }

        @Override
        public void apply(GL3 gl, int location) {
            gl.glUniformMatrix4fv(location, 1, false, columnMajor(matrix), 0);
        }
    }

    /** vecmath matrices are row-major (m01 = row 0, column 1); GLSL wants columns first. */
    static float[] columnMajor(Matrix4f m) {
        return new float[] {
            m.m00, m.m10, m.m20, m.m30,
            m.m01, m.m11, m.m21, m.m31,
            m.m02, m.m12, m.m22, m.m32,
            m.m03, m.m13, m.m23, m.m33,
        };
    }
}
