#version 330 core
// BAKED (lookup tables as in Dhillon and Ghosh 2016, Toisoul and Ghosh 2017): the spectral integral of
// 004 eq. finalexpression, sum_j |P(lambda_j)|^2 weights_j, depends on the directions only through
// (u, v, w) = -omega_i - omega_r. It is baked once per patch and settings into a 3-D table over |u|, |v| <= 2,
// w in [-2, 0] (BakedGrid) by this very file compiled with BAKE, which runs FLSS (flss.frag's spectrum and
// wavelength rule) per table sample; without BAKE each fragment reads the table with one trilinear lookup and
// multiplies by its own gain factor and shadowing (diffraction_main.glsl), which depend on the directions.
// A table of the lobes method (baked_lobes.frag bakes it: each sample averaged over its cell and the light) is
// mip-mapped and looked up over the pixel's footprint with textureGrad (BAKED_FILTERED).
#include "spectrum_gaussian.glsl"
#include "wavelengths_uniform.glsl"

// Samples of the table along u and along v (.x) and along w (.y): sample i of n sits at -2 + 4 i / (n - 1)
// (u, v) and -2 + 2 i / (n - 1) (w), both ends included (BakedGrid.uv, BakedGrid.w).
uniform vec2 bakedSamples;

#ifdef BAKE
// ---- The bake pass: pixel (i, j) of an n x n viewport is the sample (u_i, v_j) of the slice w = bakeW.
uniform float bakeW;
out vec4 fragColor;

// Only |(u, v, w)| = |omega_i + omega_r| <= 2 is reachable (about half of the box): samples farther than one cell
// diagonal beyond it (never read by a trilinear lookup of a reachable point) are 0 and cost nothing.
void main() {
    vec2 ij = floor(gl_FragCoord.xy);
    vec2 uv = -2.0 + 4.0 * ij / (bakedSamples.x - 1.0);
    vec3 uvw = vec3(uv, bakeW);
    float cellDiagonal = length(vec3(4.0 / (bakedSamples.x - 1.0), 4.0 / (bakedSamples.x - 1.0),
                                     2.0 / (bakedSamples.y - 1.0)));
    if (length(uvw) > 2.0 + cellDiagonal) {
        fragColor = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    fragColor = vec4(uniformSpectralXyz(uvw), 1.0);
}
#else
// ---- The lookup: XYZ(u, v, w) of the table (RGB), trilinear.
#ifndef BAKED_FILTERED
uniform sampler3D bakedXyz;
#endif

// Sample index t = (x - x_min) / (x_max - x_min) (n - 1) per axis; texel i's centre is at (i + 0.5) / n.
vec3 bakedTexcoord(vec3 uvw) {
    vec3 t = vec3((uvw.xy + 2.0) * 0.25 * (bakedSamples.x - 1.0), (uvw.z + 2.0) * 0.5 * (bakedSamples.y - 1.0));
    return (t + 0.5) / bakedSamples.xxy;
}

#ifdef BAKED_FILTERED
// The table as one mip-mapped 2-D layer per w sample (FloatTexture3D mipmapped): the pixel's footprint becomes
// texture-coordinate gradients in (u, v), GL picks the mip level whose cells match it (2 x 2 box averages of the
// cell-averaged samples within a slice), and the shader interpolates linearly between the two nearest w slices.
#define FILTERED 1
uniform sampler2DArray bakedLayers;
vec2 footprintGradientX;
vec2 footprintGradientY;

float texcoordPerUv() {
    return 0.25 * (bakedSamples.x - 1.0) / bakedSamples.x;
}

void setMapPixel(float halfWidth) {
    footprintGradientX = vec2(2.0 * halfWidth * texcoordPerUv(), 0.0);
    footprintGradientY = vec2(0.0, 2.0 * halfWidth * texcoordPerUv());
}

void setSurfacePixel(vec2 dUvDx, vec2 dUvDy, vec3 wi) {
    footprintGradientX = dUvDx * texcoordPerUv();
    footprintGradientY = dUvDy * texcoordPerUv();
}

// The table holds the settings' light, isotropic: another light's size is not looked up (an approximation).
void setSurfacePixelUnder(vec2 dUvDx, vec2 dUvDy, vec3 wi, float sigmaRad) {
    setSurfacePixel(dUvDx, dUvDy, wi);
}

vec3 spectralXyz(vec3 uvw) {
    vec3 tc = bakedTexcoord(uvw);
    float slice = clamp((uvw.z + 2.0) * 0.5 * (bakedSamples.y - 1.0), 0.0, bakedSamples.y - 1.0);
    float below = min(floor(slice), bakedSamples.y - 2.0);
    vec3 a = textureGrad(bakedLayers, vec3(tc.xy, below), footprintGradientX, footprintGradientY).rgb;
    vec3 b = textureGrad(bakedLayers, vec3(tc.xy, below + 1.0), footprintGradientX, footprintGradientY).rgb;
    return mix(a, b, slice - below);
}
#else
vec3 spectralXyz(vec3 uvw) {
    return texture(bakedXyz, bakedTexcoord(uvw)).rgb;
}
#endif

#include "diffraction_main.glsl"
#endif
