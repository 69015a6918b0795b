package diffract.jrtr.contexts;

import com.jogamp.opengl.GL3;
import com.jogamp.opengl.GL;
import diffract.jrtr.GlTestSupport;
import diffract.jrtr.gl.GLErrors;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * A second offscreen context made, used and released on the thread of a first (what a table bake does beside a
 * render) leaves the first's objects usable: vertex arrays and buffers generated in the first context after the
 * switch bind without GL errors, with the second context alive and after it is destroyed, and so do those of a
 * context made on the thread afterwards.
 */
@Tag("gl")
class ContextSwitchTest {

    @Test
    void objectsOfTheFirstContextBindAfterASecondContextWasCurrent() {
        GlTestSupport.assumeOffscreenGl();
        OffscreenContext first = HeadlessGL.newContext();
        GL3 gl = first.makeCurrent();
        try {
            bindNewObjects(gl, "in the first context");
            OffscreenContext second = HeadlessGL.newContext();
            GL3 gl2 = second.makeCurrent();
            try {
                bindNewObjects(gl2, "in the second context");
            } finally {
                second.release();
            }
            bindNewObjects(gl, "in the first context, the second alive");
            second.destroy();
            bindNewObjects(gl, "in the first context, the second destroyed");
        } finally {
            first.release();
            first.destroy();
        }
        OffscreenContext later = HeadlessGL.newContext();
        try {
            bindNewObjects(later.makeCurrent(), "in a context made after both");
        } finally {
            later.release();
            later.destroy();
        }
    }

    private static void bindNewObjects(GL3 gl, String where) {
        GLErrors.check(gl, "before binding new objects " + where);
        int[] vertexArray = new int[1];
        gl.glGenVertexArrays(1, vertexArray, 0);
        gl.glBindVertexArray(vertexArray[0]);
        int[] buffer = new int[1];
        gl.glGenBuffers(1, buffer, 0);
        gl.glBindBuffer(GL.GL_ARRAY_BUFFER, buffer[0]);
        gl.glBufferData(GL.GL_ARRAY_BUFFER, 16, java.nio.FloatBuffer.wrap(new float[] {0, 1, 2, 3}),
                GL.GL_STATIC_DRAW);
        gl.glBindVertexArray(0);
        gl.glBindBuffer(GL.GL_ARRAY_BUFFER, 0);
        GLErrors.check(gl, "binding a new vertex array and buffer " + where);
        gl.glDeleteBuffers(1, buffer, 0);
        gl.glDeleteVertexArrays(1, vertexArray, 0);
    }
}
