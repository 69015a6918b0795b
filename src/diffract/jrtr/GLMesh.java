package diffract.jrtr;

import com.jogamp.opengl.GL3;
import com.jogamp.opengl.GL;
import diffract.jrtr.gl.GLErrors;
import diffract.jrtr.scenegraph.VertexAttribute;
import diffract.jrtr.scenegraph.VertexData;

import java.nio.FloatBuffer;
import java.nio.IntBuffer;

/**
 * The GPU copy of one {@link VertexData}: a vertex array object with one buffer per attribute (at the fixed
 * {@link VertexAttribute#location()}) and an index buffer; drawn as indexed GL_TRIANGLES.
 */
final class GLMesh {
    private final int vertexArray;
    private final int[] buffers;
    private final int indexCount;

    private GLMesh(int vertexArray, int[] buffers, int indexCount) {
        this.vertexArray = vertexArray;
        this.buffers = buffers;
        this.indexCount = indexCount;
    }

    static GLMesh upload(GL3 gl, VertexData data) {
        int[] vao = new int[1];
        gl.glGenVertexArrays(1, vao, 0);
        gl.glBindVertexArray(vao[0]);
        int[] buffers = new int[VertexAttribute.values().length + 1];
        gl.glGenBuffers(buffers.length, buffers, 0);
        for (VertexAttribute attribute : VertexAttribute.values()) {
            if (!data.has(attribute)) {
                // the shader then reads the constant current attribute value, (0, 0, 0, 1)
                gl.glDisableVertexAttribArray(attribute.location());
                continue;
            }
            float[] values = data.attributeView(attribute);
            gl.glBindBuffer(GL.GL_ARRAY_BUFFER, buffers[attribute.location()]);
            gl.glBufferData(GL.GL_ARRAY_BUFFER, (long) values.length * Float.BYTES, FloatBuffer.wrap(values),
                    GL.GL_STATIC_DRAW);
            gl.glVertexAttribPointer(attribute.location(), attribute.components(), GL.GL_FLOAT, false, 0, 0L);
            gl.glEnableVertexAttribArray(attribute.location());
        }
        int[] indices = data.indicesView();
        // the element buffer binding is VAO state, so it must be bound while the VAO is
        gl.glBindBuffer(GL.GL_ELEMENT_ARRAY_BUFFER, buffers[buffers.length - 1]);
        gl.glBufferData(GL.GL_ELEMENT_ARRAY_BUFFER, (long) indices.length * Integer.BYTES, IntBuffer.wrap(indices),
                GL.GL_STATIC_DRAW);
        gl.glBindVertexArray(0);
        gl.glBindBuffer(GL.GL_ARRAY_BUFFER, 0);
        GLErrors.check(gl, "uploading a mesh of " + data.vertexCount() + " vertices");
        return new GLMesh(vao[0], buffers, indices.length);
    }

    void draw(GL3 gl) {
        gl.glBindVertexArray(vertexArray);
        gl.glDrawElements(GL.GL_TRIANGLES, indexCount, GL.GL_UNSIGNED_INT, 0L);
        gl.glBindVertexArray(0);
    }

    void delete(GL3 gl) {
        gl.glDeleteVertexArrays(1, new int[] {vertexArray}, 0);
        gl.glDeleteBuffers(buffers.length, buffers, 0);
    }
}
