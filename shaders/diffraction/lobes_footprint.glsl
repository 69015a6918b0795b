// What a pixel of the lobes method averages over (Footprint, LightSource, LobeGeometry on the CPU): a BRDF-map
// pixel's square in (u, v) with the light's Gaussian folded into each axis (define LOBES_BOX), or a surface pixel's
// Gaussian (its screen-space derivatives) plus the light's. Included by lobes.frag. llvmpipe runs a group of
// fragments in SIMD lanes and executes both sides of every branch under a mask, so the box and the Gaussian are
// separate builds and the arithmetic below selects rather than branches.
#ifndef LOBES_FOOTPRINT_GLSL
#define LOBES_FOOTPRINT_GLSL
#include "diffraction_common.glsl"
#include "footprint_covariance.glsl"

// LIGHT_NODES_MAX: the light arrays' size, a define from DiffractionMaterials.LIGHT_NODES_MAX (DiffractionShaders)

// 1: surface pixels average over their footprint (PixelFilter.BOX); 0: the centre direction only
// (PixelFilter.POINT). A BRDF map's box is the define LOBES_BOX.
uniform float pixelFootprintScale;
// BRDF maps (one omega_i per map): the light's (u, v) covariance split on the CPU (Covariance2.diagonalPlusRankOne)
// into a diagonal part (variances along u and v) and Gauss-Hermite shifts along the rest: (du, dv, weight) per node.
uniform vec2 lightDiagonal;
uniform vec3 lightRankOne; // the rest, (xx, xy, yy): a point pixel takes the light's full covariance
uniform float lightShifts[3 * LIGHT_NODES_MAX];
uniform int lightShiftCount;
// Surfaces: sigma_a = D / 4 of the light in radians (LightSource.sigmaRad); its covariance follows omega_i.
uniform float lightSigmaRad;

// The footprint of the fragment being shaded, set by setMapPixel or setSurfacePixel before spectralXyz runs.
vec2 footprintHalfWidth;   // the box's half-widths in (u, v) (0: none)
vec3 footprintGaussian;    // (xx, xy, yy): the Gaussian convolved with the box (diagonal when there is a box)
int footprintShiftCount;   // Gauss-Hermite shifts of the light's off-axis part (box only; 1 = none)

// A BRDF-map pixel of an S x S map: a square of half-width 1 / S (Footprint.mapPixel) with LOBES_BOX, else its
// centre (PixelFilter.POINT); the light from uniforms.
void setMapPixel(float halfWidth) {
#ifdef LOBES_BOX
    footprintHalfWidth = vec2(halfWidth);
    footprintGaussian = vec3(lightDiagonal.x, 0.0, lightDiagonal.y);
    footprintShiftCount = max(lightShiftCount, 1);
#else
    // no box: the light's full Gaussian is the footprint
    footprintHalfWidth = vec2(0.0);
    footprintGaussian = vec3(lightDiagonal.x, 0.0, lightDiagonal.y) + lightRankOne;
    footprintShiftCount = 1;
#endif
}

// A sample of the baked table (baked.frag's bake pass): the box of its cell, half-width halfWidth in u and v, and the
// light as an isotropic Gaussian of sigma_a (its spread at normal incidence: the table does not know omega_i).
void setTableCell(float halfWidth) {
    footprintHalfWidth = vec2(halfWidth);
    footprintGaussian = vec3(lightSigmaRad * lightSigmaRad, 0.0, lightSigmaRad * lightSigmaRad);
    footprintShiftCount = 1;
}

// A surface pixel lit by a light of sigma_a = sigmaRad: the Gaussian (J_x J_x^T + J_y J_y^T) / 12 of its (u, v)
// derivatives (Footprint.surfacePixel), plus the light's covariance at omega_i.
void setSurfacePixelUnder(vec2 dUvDx, vec2 dUvDy, vec3 wi, float sigmaRad) {
    vec3 pixel = pixelFootprintScale * pixelCovariance(dUvDx, dUvDy);
    footprintHalfWidth = vec2(0.0);
    footprintGaussian = pixel + lightCovariance(wi, sigmaRad);
    footprintShiftCount = 1;
}

// A surface pixel under the settings' light (lightSigmaRad).
void setSurfacePixel(vec2 dUvDx, vec2 dUvDy, vec3 wi) {
    setSurfacePixelUnder(dUvDx, dUvDy, wi, lightSigmaRad);
}

// ErrorFunction.fastErfc for x >= 0: Abramowitz and Stegun 7.1.26, absolute error below 1.5e-7.
float erfcPositive(float x) {
    float t = 1.0 / (1.0 + 0.3275911 * x);
    return t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))))
            * exp(-x * x);
}

// ErrorFunction.fastMassInInterval: (erf(b) - erf(a)) / 2 on the side where it does not cancel, from erfc(|a|) and
// erfc(|b|) only (two exponentials; selects, not branches, so no lane evaluates a third).
float massInInterval(float a, float b) {
    float ea = erfcPositive(abs(a));
    float eb = erfcPositive(abs(b));
    float sameSide = a >= 0.0 ? ea - eb : eb - ea;
    return 0.5 * (a < 0.0 && b > 0.0 ? 2.0 - ea - eb : sameSide);
}

#ifdef LOBES_BOX
// LobeGeometry.axis with a box: sqrt(pi) sigmaUv times the average over [u - h, u + h] of N(mu, variance).
float lobeAxis(float sigmaUv, float variance, float mu, float u, float h) {
    float scale = 1.0 / (1.41421356 * sqrt(variance));
    // the fast erf's absolute error (1.5e-7) could make a far tail's mass slightly negative
    float mass = max(0.0, massInInterval((u - h - mu) * scale, (u + h - mu) * scale));
    return 1.77245385 * sigmaUv * mass / (2.0 * h);
}
#endif

// LobeGeometry.averagedLobe: the lobe of spread sigmaUv at mu, averaged over the fragment's footprint at uv (peak 1
// for a point on the lobe's centre). LOBES_BOX (a BRDF map's pixel square, a baked table's cell) or a Gaussian.
float averagedLobe(float sigmaUv, vec2 mu, vec2 uv) {
    float lobeVariance = 0.5 * sigmaUv * sigmaUv;
#ifdef LOBES_BOX
    float sum = 0.0;
    for (int k = 0; k < LIGHT_NODES_MAX; k++) {
        if (k >= footprintShiftCount) {
            break;
        }
        vec3 shift = lightShiftCount > 0 ? vec3(lightShifts[3 * k], lightShifts[3 * k + 1], lightShifts[3 * k + 2])
                : vec3(0.0, 0.0, 1.0);
        vec2 at = uv + shift.xy;
        sum += shift.z * lobeAxis(sigmaUv, lobeVariance + footprintGaussian.x, mu.x, at.x, footprintHalfWidth.x)
                * lobeAxis(sigmaUv, lobeVariance + footprintGaussian.z, mu.y, at.y, footprintHalfWidth.y);
    }
    return sum;
#else
    vec3 s = footprintGaussian + vec3(lobeVariance, 0.0, lobeVariance);
    float det = s.x * s.z - s.y * s.y;
    vec2 d = uv - mu;
    float q = (s.z * d.x * d.x - 2.0 * s.y * d.x * d.y + s.x * d.y * d.y) / det;
    return sigmaUv * sigmaUv / (2.0 * sqrt(det)) * exp(-0.5 * q);
#endif
}

#endif
