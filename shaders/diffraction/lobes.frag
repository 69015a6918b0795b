#version 330 core
// LOBES: the windowed spectrum as a sum of Gaussian lobes, one per DFT texel m (pairs m != m' are below the
// pair threshold for the patches this shader is given: DiffractionTextures refuses others), each widened by the
// pixel's footprint and the light and integrated over wavelength by a rule fitted to its passage. Mirrors
// diffract.optics.LobeSpectrum step for step (docs/design/filtering.md, section 4):
//   1. march over the texels near the segment s(lambda) = (u L_x, v L_y) / lambda along its major axis; a texel's
//      lobe sits at mu(lambda) = lambda m / L in (u, v) and comes within reach of the footprint over an interval of
//      wavelengths (a linear inequality per axis); texels out of reach are skipped before any fetch;
//   2. a texel's Taylor terms are fetched once; T_m(k w) is evaluated from them every lobeWeightStepNm of the lobe's
//      passage and linearly interpolated between (with the footprint's average along an axis the lobe does not move
//      on);
//   3. nodes lambda_min + j h, h = the passage's width over the nodes per sigma, on 1, 2, 4, 8, 16 nm (hat-filtered
//      spectral weights) or below 1 nm (point weights): HatFilteredSpectrum;
//   4. the lobe averaged over the footprint at each node (lobes_footprint.glsl).
#define FILTERED 1
#include "lobes_spectrum.glsl"
#include "diffraction_main.glsl"
