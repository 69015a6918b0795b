package diffract.render;

import diffract.jrtr.scenegraph.Material;
import diffract.optics.BrdfSettings;

/**
 * PQ on the GPU ({@code pq.frag}): the series under the sinc window of the patch's replicas.
 *
 * <table>
 *   <caption>Uniforms</caption>
 *   <tr><th>uniform</th><th>from</th></tr>
 *   <tr><td>{@code uniformNodeTable}</td><td>the uniform wavelengths' spectral weights</td></tr>
 *   <tr><td>{@code pqReplicas}</td><td>the replica counts per axis of DiffractionBrdf.create(PQ)</td></tr>
 * </table>
 */
final class PqGpu implements GpuMethod {
    @Override
    public void setUniforms(Material m, DiffractionTextures textures, BrdfSettings settings) {
        m.setTexture("uniformNodeTable", textures.uniformNodeTable());
        m.setVec2("pqReplicas", settings.window().replicas(settings.coherenceWindow(), textures.extentXUm()),
                settings.window().replicas(settings.coherenceWindow(), textures.extentYUm()));
    }
}
