package diffract.jrtr.gl;

import com.jogamp.opengl.GL;

/** Turns pending {@code glGetError} codes into an exception that says where they were noticed. */
public final class GLErrors {
    private GLErrors() {
    }

    /** Throws {@link IllegalStateException} naming all pending GL errors and {@code where}; no-op if none. */
    public static void check(GL gl, String where) {
        int error = gl.glGetError();
        if (error == GL.GL_NO_ERROR) {
            return;
        }
        StringBuilder names = new StringBuilder();
        for (int i = 0; i < 16 && error != GL.GL_NO_ERROR; i++) {
            if (names.length() > 0) {
                names.append(", ");
            }
            names.append(name(error));
            error = gl.glGetError();
        }
        throw new IllegalStateException("OpenGL error " + names + " " + where);
    }

    public static String name(int error) {
        switch (error) {
            case GL.GL_INVALID_ENUM:
                return "GL_INVALID_ENUM";
            case GL.GL_INVALID_VALUE:
                return "GL_INVALID_VALUE";
            case GL.GL_INVALID_OPERATION:
                return "GL_INVALID_OPERATION";
            case GL.GL_INVALID_FRAMEBUFFER_OPERATION:
                return "GL_INVALID_FRAMEBUFFER_OPERATION";
            case GL.GL_OUT_OF_MEMORY:
                return "GL_OUT_OF_MEMORY";
            default:
                return "0x" + Integer.toHexString(error);
        }
    }
}
