package diffract.jrtr;

import com.jogamp.opengl.GL;
import com.jogamp.opengl.GL2ES2;

/** What the driver says about itself: for logs, reports and error messages. */
public record GLInfo(String version, String renderer, String vendor, String glslVersion, boolean coreProfile) {
    /** Queries the current context. */
    public static GLInfo of(GL gl) {
        return new GLInfo(gl.glGetString(GL.GL_VERSION), gl.glGetString(GL.GL_RENDERER),
                gl.glGetString(GL.GL_VENDOR), gl.glGetString(GL2ES2.GL_SHADING_LANGUAGE_VERSION),
                gl.getContext().isGLCoreProfile());
    }

    @Override
    public String toString() {
        return "OpenGL " + version + (coreProfile ? " core" : "") + ", " + renderer + " (" + vendor + "), GLSL "
                + glslVersion;
    }
}
