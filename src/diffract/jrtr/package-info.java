/**
 * jrtr: a small real-time rendering engine over JOGL (OpenGL 3.3 core or newer), after the engine of the same
 * name used in M. Single's thesis. It knows scenes, cameras, shaders, textures and framebuffers, and nothing of
 * what the shaders compute.
 *
 * <ul>
 *   <li>Scene graph: {@link diffract.jrtr.scenegraph.Group}, {@link diffract.jrtr.scenegraph.TransformGroup},
 *       {@link diffract.jrtr.scenegraph.ShapeNode} (a {@link diffract.jrtr.scenegraph.Shape} drawn with a
 *       {@link diffract.jrtr.scenegraph.Material}), {@link diffract.jrtr.scenegraph.LightNode}; flattened by
 *       {@link diffract.jrtr.scenegraph.RenderList}.</li>
 *   <li>Viewing: {@link diffract.jrtr.scenegraph.Camera} (eye, look-at, up) and
 *       {@link diffract.jrtr.scenegraph.Frustum}.</li>
 *   <li>Shaders: {@link diffract.jrtr.scenegraph.ShaderProgram} from the classpath ({@code /shaders}) or a directory,
 *       with injected {@code #define}s, {@code #include "file.glsl"} and errors reported as
 *       {@code file.glsl:LINE}.</li>
 *   <li>Textures, uploaded once: {@link diffract.jrtr.textures.Texture2D},
 *       {@link diffract.jrtr.textures.FloatTextureArray}, {@link diffract.jrtr.textures.FloatTexture1D}.</li>
 *   <li>Drawing: {@link diffract.jrtr.Renderer} (a GLEventListener) into an
 *       {@link diffract.jrtr.OffscreenTarget} (RGBA32F, read back as floats) or an
 *       {@link diffract.jrtr.contexts.OnscreenWindow}; {@link diffract.jrtr.gl.GpuTimer} measures GPU time.</li>
 * </ul>
 *
 * <pre>{@code
 * Material red = new Material(ShaderProgram.fromClasspath("engine/unlit.vert", "engine/unlit.frag", Map.of()))
 *         .setVec4("color", 1, 0, 0, 1);
 * Group scene = new Group("scene").add(new ShapeNode(Shapes.cube(1), red));
 * try (OffscreenTarget target = new OffscreenTarget(new Renderer(scene, new Camera(), new Frustum()))) {
 *     target.writePng(Path.of("out/cube.png"), 128, 128);
 * }
 * }</pre>
 *
 * <p>Offscreen targets need no X server: {@link diffract.jrtr.contexts.HeadlessGL} gives them headless EGL (any GPU, or
 * Mesa's llvmpipe) and falls back to JOGL on the X display; windows need a display, which
 * {@link diffract.jrtr.contexts.DisplayCheck} checks in one line. See docs/guide/headless-gl.md.
 */
package diffract.jrtr;
