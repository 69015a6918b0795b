// Spectral integration on the uniform grid of FLSS and PQ (WavelengthSampling.uniform; 003 Algorithm 3 lines
// 4-26): XYZ = sum_j |P(lambda_j)|^2 weights_j.
#ifndef WAVELENGTHS_UNIFORM_GLSL
#define WAVELENGTHS_UNIFORM_GLSL
#include "diffraction_common.glsl"

// Entry j = (wx_j, wy_j, wz_j, lambda_j in nm): the trapezoid x D65 x CMF weights of SpectralIntegrator.xyzWeights,
// already normalised so that a flat mirror is D65 white at Y = 1, and the node itself.
uniform sampler1D uniformNodeTable;

float patchPower(vec3 uvw, float lambdaNm);

vec3 uniformSpectralXyz(vec3 uvw) {
    int count = textureSize(uniformNodeTable, 0);
    vec3 xyz = vec3(0.0);
    for (int j = 0; j < count; j++) {
        vec4 node = texelFetch(uniformNodeTable, j, 0);
        xyz += patchPower(uvw, node.w) * node.xyz;
    }
    return xyz;
}

#endif
