package diffract.render;

import diffract.jrtr.scenegraph.Material;
import diffract.optics.BrdfSettings;

/**
 * NMM on the GPU ({@code nmm.frag}): FLSS's series at wavelengths placed per pixel, with FLSS's uniform grid as its
 * fallback.
 *
 * <table>
 *   <caption>Uniforms beyond FLSS's</caption>
 *   <tr><th>uniform</th><th>from</th></tr>
 *   <tr><td>{@code spectralTable}, {@code spectralTableFirstNm}</td><td>the CMFs and D65 per nanometre</td></tr>
 *   <tr><td>{@code lambdaMinNm}, {@code lambdaMaxNm}</td><td>the band</td></tr>
 * </table>
 */
final class NmmGpu extends FlssGpu {
    @Override
    public void setUniforms(Material m, DiffractionTextures textures, BrdfSettings settings) {
        super.setUniforms(m, textures, settings);
        m.setTexture("spectralTable", textures.spectralTable())
                .setFloat("spectralTableFirstNm", (float) textures.spectralTableFirstNm())
                .setFloat("lambdaMinNm", (float) settings.spectral().lambdaMinNm())
                .setFloat("lambdaMaxNm", (float) settings.spectral().lambdaMaxNm());
    }
}
