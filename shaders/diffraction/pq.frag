#version 330 core
// PQ (003 section 1.5.3; 004 "PQ factors"): sinc interpolation between DFT texels times the replication factor,
// on the uniform wavelength grid. Mirrors DiffractionBrdf.create(PQ): TaylorSincSpectrum + WavelengthSampling.uniform.
#include "spectrum_sinc.glsl"
#include "wavelengths_uniform.glsl"

vec3 spectralXyz(vec3 uvw) {
    return uniformSpectralXyz(uvw);
}

#include "diffraction_main.glsl"
