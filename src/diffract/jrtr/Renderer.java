package diffract.jrtr;

import com.jogamp.opengl.GLAutoDrawable;
import com.jogamp.opengl.GLEventListener;
import diffract.jrtr.contexts.OnscreenWindow;
import diffract.jrtr.gl.PixelRect;
import diffract.jrtr.scenegraph.Camera;
import diffract.jrtr.scenegraph.Frustum;
import diffract.jrtr.scenegraph.Node;

/**
 * Draws a scene graph seen through a camera and frustum. It is a plain JOGL {@link GLEventListener}, so the
 * same object renders into a window ({@link OnscreenWindow}, or any GLWindow/GLCanvas it is added to) or into
 * an {@link OffscreenTarget}. It draws into whatever framebuffer is bound when {@link #display} is called. It
 * serves one drawable at a time (it holds that drawable's render context between init and dispose).
 * Subclasses may override {@link #display} and draw more (e.g. an overlay) after {@code super.display}.
 */
public class Renderer implements GLEventListener {
    private Node root;
    private Camera camera;
    private Frustum frustum;
    private final float[] clearColor = {0, 0, 0, 1};
    private GLRenderContext context;
    private int viewportWidth;
    private int viewportHeight;

    public Renderer(Node root, Camera camera, Frustum frustum) {
        this.root = root;
        this.camera = camera;
        this.frustum = frustum;
    }

    public Node root() {
        return root;
    }

    public void setRoot(Node root) {
        this.root = root;
    }

    public Camera camera() {
        return camera;
    }

    public void setCamera(Camera camera) {
        this.camera = camera;
    }

    public Frustum frustum() {
        return frustum;
    }

    public void setFrustum(Frustum frustum) {
        this.frustum = frustum;
    }

    public void setClearColor(float red, float green, float blue, float alpha) {
        clearColor[0] = red;
        clearColor[1] = green;
        clearColor[2] = blue;
        clearColor[3] = alpha;
    }

    /** The render context; null before {@link #init} and after {@link #dispose}. */
    public GLRenderContext context() {
        return context;
    }

    @Override
    public void init(GLAutoDrawable drawable) {
        context = new GLRenderContext(drawable.getGL());
        viewportWidth = drawable.getSurfaceWidth();
        viewportHeight = drawable.getSurfaceHeight();
    }

    /** Keeps the picture undistorted: the frustum's aspect follows the viewport's. */
    @Override
    public void reshape(GLAutoDrawable drawable, int x, int y, int width, int height) {
        viewportWidth = width;
        viewportHeight = height;
        if (width > 0 && height > 0) {
            frustum.setAspect((float) width / height);
        }
    }

    @Override
    public void display(GLAutoDrawable drawable) {
        if (context == null) {
            throw new IllegalStateException("Renderer.display before init");
        }
        if (viewportWidth <= 0 || viewportHeight <= 0) {
            return; // minimised window: nothing to draw
        }
        context.setViewport(0, 0, viewportWidth, viewportHeight);
        context.clear(clearColor[0], clearColor[1], clearColor[2], clearColor[3]);
        context.draw(root, camera, frustum);
    }

    /**
     * Clears and draws only {@code tile} of a {@code width} x {@code height} viewport of the bound framebuffer: one
     * part of a frame drawn in parts, so no single draw call runs long (a software rasteriser takes seconds for a
     * full frame of an expensive shader). The frustum keeps its aspect: a viewport of another size than the
     * window's (a frame at a fraction of its resolution) shows the same picture.
     */
    public void displayTile(int width, int height, PixelRect tile) {
        if (context == null) {
            throw new IllegalStateException("Renderer.displayTile before init");
        }
        context.setViewport(0, 0, width, height);
        context.setScissor(tile);
        try {
            context.clear(clearColor[0], clearColor[1], clearColor[2], clearColor[3]);
            context.draw(root, camera, frustum);
        } finally {
            context.setScissor(null);
        }
    }

    @Override
    public void dispose(GLAutoDrawable drawable) {
        if (context != null) {
            context.dispose();
            context = null;
        }
    }
}
