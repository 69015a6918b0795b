package diffract.render;

import diffract.jrtr.scenegraph.Material;
import diffract.optics.BrdfSettings;

/**
 * FLSS on the GPU ({@code flss.frag}): the thesis' series under the Gaussian window at uniformly spaced wavelengths.
 *
 * <table>
 *   <caption>Uniforms</caption>
 *   <tr><th>uniform</th><th>from</th></tr>
 *   <tr><td>{@code uniformNodeTable}</td><td>the uniform wavelengths' spectral weights (DiffractionTextures)</td></tr>
 *   <tr><td>{@code sigmaTexels}</td><td>the coherence window, sigma_f in texels per axis</td></tr>
 * </table>
 */
class FlssGpu implements GpuMethod {
    @Override
    public void setUniforms(Material m, DiffractionTextures textures, BrdfSettings settings) {
        m.setTexture("uniformNodeTable", textures.uniformNodeTable());
        GpuMethod.gaussianWindow(m, textures, settings);
    }

    /** Its table's samples are FLSS at each (u, v, w) point ({@code baked.frag} with {@code BAKE}). */
    @Override
    public String bakeFragmentPath() {
        return "diffraction/baked.frag";
    }

    @Override
    public void addBakeDefines(java.util.Map<String, String> defines, BrdfSettings settings) {
        defines.put("BAKE", "1");
    }
}
