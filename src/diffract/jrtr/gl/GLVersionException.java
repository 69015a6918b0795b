package diffract.jrtr.gl;

/** The OpenGL context is older than the engine needs (3.3 core); the message names both versions. */
public class GLVersionException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public GLVersionException(String message) {
        super(message);
    }
}
