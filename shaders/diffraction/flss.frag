#version 330 core
// FLSS, full lambda-space sampling (003 Algorithm 3): Gaussian-windowed Taylor series on the uniform wavelength
// grid. Mirrors DiffractionBrdf.create(FLSS): TaylorGaussianSpectrum + WavelengthSampling.uniform.
#include "spectrum_gaussian.glsl"
#include "wavelengths_uniform.glsl"

vec3 spectralXyz(vec3 uvw) {
    return uniformSpectralXyz(uvw);
}

#include "diffraction_main.glsl"
