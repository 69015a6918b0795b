package diffract.jrtr.scenegraph;

import diffract.jrtr.contexts.GLInfo;
import diffract.jrtr.gl.PixelRect;

/**
 * Draws scenes into whatever framebuffer is bound (a window or an offscreen target). Implementations upload
 * each shape's geometry once, compile each material's program and upload its textures on first use, and free
 * all of it in {@link #dispose}. All methods must be called with the context's GL context current (inside a
 * {@code GLEventListener} callback, or via {@code OffscreenTarget.withContext}).
 *
 * <p>Per draw the engine sets these uniforms when the program declares them: {@code mat4 model, view,
 * projection}, {@code mat3 normalMatrix} (inverse transpose of the model's 3x3 part), {@code vec3
 * cameraPosition} (world space), {@code int lightCount}, {@code vec3 lightDirection[MAX_LIGHTS]} (world space,
 * towards the light) and {@code vec3 lightRadiance[MAX_LIGHTS]}. Material uniforms are set afterwards, so a
 * material may override them.
 */
public interface RenderContext {
    /** Most lights passed to shaders; shaders declare their arrays with at least this size. */
    int MAX_LIGHTS = 8;

    /** The uniforms the engine sets per draw (above); a material sets every other uniform its program uses. */
    java.util.Set<String> ENGINE_UNIFORMS = java.util.Set.of("model", "view", "projection", "normalMatrix",
            "cameraPosition", "lightCount", "lightDirection", "lightRadiance");

    /** The driver's version and renderer strings. */
    GLInfo info();

    /** The pixel rectangle to draw into. */
    void setViewport(int x, int y, int width, int height);

    /**
     * Restricts drawing and clearing to {@code rect} of the viewport's framebuffer (a tile of a frame drawn in
     * parts), or lifts the restriction with null.
     */
    void setScissor(PixelRect rect);

    /** Clears colour (to the given RGBA) and depth. */
    void clear(float red, float green, float blue, float alpha);

    /** Draws every shape of {@code list} with depth testing, lit by the list's lights. */
    void draw(RenderList list, Camera camera, Frustum frustum);

    /** Flattens the scene graph under {@code root} and draws it. */
    default void draw(Node root, Camera camera, Frustum frustum) {
        draw(RenderList.collect(root), camera, frustum);
    }

    /** Frees every GPU object this context created (meshes, programs, textures). */
    void dispose();
}
