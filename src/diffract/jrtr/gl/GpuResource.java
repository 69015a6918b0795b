package diffract.jrtr.gl;

import com.jogamp.opengl.GL;
import com.jogamp.opengl.GL3;

/**
 * Something with a CPU description that is copied to the GPU once, on first use, and lives there until
 * disposed. It belongs to the GL context that uploaded it; using it from another context is an error (our
 * contexts do not share objects), reported instead of silently drawing garbage.
 */
public abstract class GpuResource {
    private Object owner;

    /** Whether the GPU copy exists. */
    public final boolean isUploaded() {
        return owner != null;
    }

    /** Uploads on the first call; later calls from the same context do nothing. */
    public final void upload(GL3 gl) {
        Object current = owner(gl);
        if (owner == null) {
            createOnGpu(gl);
            owner = current;
        } else if (owner != current) {
            throw new IllegalStateException(this + " was uploaded to another GL context; give each context its own");
        }
    }

    /** Frees the GPU copy (no-op if there is none); the resource can be uploaded again afterwards. */
    public final void dispose(GL3 gl) {
        if (owner == null) {
            return;
        }
        if (owner != owner(gl)) {
            throw new IllegalStateException(this + " belongs to another GL context and must be disposed there");
        }
        deleteOnGpu(gl);
        owner = null;
    }

    /**
     * What identifies the context behind {@code gl}: JOGL's context object, or, for GLs without one (the headless
     * EGL context's), the GL object itself, which is one per context.
     */
    static Object owner(GL gl) {
        Object context = gl.getContext();
        return context != null ? context : gl;
    }

    /** Creates the GL objects; called with the owning context current. */
    protected abstract void createOnGpu(GL3 gl);

    /** Deletes the GL objects; called with the owning context current. */
    protected abstract void deleteOnGpu(GL3 gl);
}
