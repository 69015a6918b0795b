#version 330 core
// NMM (003 section 1.5.2): the Gaussian-windowed Taylor series evaluated only at the wavelengths that land on DFT
// texel centres, trapezoid rule on those nodes (the Jacobian), uniform grid as the fallback.
// Mirrors DiffractionBrdf.create(NMM): TaylorGaussianSpectrum + WavelengthSampling.nmm.
#include "spectrum_gaussian.glsl"
#include "wavelengths_nmm.glsl"

vec3 spectralXyz(vec3 uvw) {
    vec3 xyz;
    return nmmSpectralXyz(uvw, xyz) ? xyz : uniformSpectralXyz(uvw);
}

#include "diffraction_main.glsl"
