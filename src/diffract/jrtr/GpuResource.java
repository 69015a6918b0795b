package diffract.jrtr;

import com.jogamp.opengl.GL3;
import com.jogamp.opengl.GLContext;

/**
 * Something with a CPU description that is copied to the GPU once, on first use, and lives there until
 * disposed. It belongs to the GL context that uploaded it; using it from another context is an error (our
 * contexts do not share objects), reported instead of silently drawing garbage.
 */
public abstract class GpuResource {
    private GLContext owner;

    /** Whether the GPU copy exists. */
    public final boolean isUploaded() {
        return owner != null;
    }

    /** Uploads on the first call; later calls from the same context do nothing. */
    public final void upload(GL3 gl) {
        GLContext current = gl.getContext();
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
        if (owner != gl.getContext()) {
            throw new IllegalStateException(this + " belongs to another GL context and must be disposed there");
        }
        deleteOnGpu(gl);
        owner = null;
    }

    /** Creates the GL objects; called with the owning context current. */
    protected abstract void createOnGpu(GL3 gl);

    /** Deletes the GL objects; called with the owning context current. */
    protected abstract void deleteOnGpu(GL3 gl);
}
