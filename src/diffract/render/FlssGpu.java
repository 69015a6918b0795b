package diffract.render;

import diffract.jrtr.Material;
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
}
