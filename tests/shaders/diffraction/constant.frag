#version 330 core
// The toy method of ToyMethodTest (a test resource): |P|^2 = 0.02 at every (u, v, w) and wavelength, summed on the
// uniform wavelength grid as its CPU twin sums it (WavelengthSampling.uniform).
#include "wavelengths_uniform.glsl"

// diffraction_common.glsl's windowed sum over texels, which a constant BRDF does not use.
float windowWeight(float offsetTexels, int axis) {
    return 0.0;
}

float patchPower(vec3 uvw, float lambdaNm) {
    return 0.02;
}

vec3 spectralXyz(vec3 uvw) {
    return uniformSpectralXyz(uvw);
}

#include "diffraction_main.glsl"
