// |P|^2 with the Gaussian coherence window (FLSS and NMM): TaylorGaussianSpectrum, 003 Algorithm 3.
#ifndef SPECTRUM_GAUSSIAN_GLSL
#define SPECTRUM_GAUSSIAN_GLSL
#include "diffraction_common.glsl"

// sigma_f in texels per axis, L / (2 pi sigma_s) (CoherenceWindow.sigmaTexels; 004 eq.
// gaussianwindowfrequencyspace). Positive: set from BrdfSettings, which rejects sigma_s <= 0.
uniform vec2 sigmaTexels;

// exp(-d^2 / (2 sigma^2)), peak 1 so that a flat mirror stays 1 (CoherenceWindow.weight).
float windowWeight(float offsetTexels, int axis) {
    float q = offsetTexels / sigmaTexels[axis];
    return exp(-0.5 * q * q);
}

// |P(lambda)|^2 (TaylorGaussianSpectrum.power).
float patchPower(vec3 uvw, float lambdaNm) {
    return windowedTaylorPower(uvw, lambdaNm);
}

#endif
