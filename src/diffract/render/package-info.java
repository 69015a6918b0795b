/**
 * The diffraction shaders on the GPU: the application layer that knows both the optics ({@code diffract.optics},
 * {@code diffract.colour}) and the engine ({@code diffract.jrtr}), which knows nothing of diffraction.
 *
 * <ul>
 *   <li>{@link diffract.render.DiffractionShaders}: which GLSL program of {@code shaders/diffraction/} a variant
 *       uses and its compile-time {@code #define}s.</li>
 *   <li>{@link diffract.render.DiffractionTextures}: the Taylor terms as an RG32F (or RG16F) texture array and
 *       the spectral lookup tables, uploaded once.</li>
 *   <li>{@link diffract.render.DiffractionMaterials}: {@link diffract.jrtr.scenegraph.Material}s for BRDF maps and
 *       meshes.</li>
 *   <li>{@link diffract.render.GpuBrdfMap}: a BRDF map rendered offscreen with the pixel convention of
 *       {@link diffract.optics.BrdfMap}, returned as float XYZ (or the monochromatic relative BRDF) for the same
 *       colour pipeline as the CPU's maps, and its GPU time per frame.</li>
 * </ul>
 *
 * The shaders compute in float32 what the CPU variants ({@link diffract.optics.DiffractionBrdf}) compute in
 * double; the tests of this package hold them to the same pictures.
 */
package diffract.render;
