#version 330 core
// BAKED (lookup tables as in Dhillon and Ghosh 2016, Toisoul and Ghosh 2017): the spectral integral of
// 004 eq. finalexpression, sum_j |P(lambda_j)|^2 weights_j, depends on the directions only through
// (u, v, w) = -omega_i - omega_r. It is baked once per patch and settings into a 3-D table over |u|, |v| <= 2,
// w in [-2, 0] (BakedGrid) by this very file compiled with BAKE, which runs FLSS (flss.frag's spectrum and
// wavelength rule) per table sample; without BAKE each fragment reads the table with one trilinear lookup and
// multiplies by its own gain factor and shadowing (diffraction_main.glsl), which depend on the directions.
// A table of the lobes method (baked_lobes.frag bakes it: each sample averaged over its cell and the light) is
// mip-mapped and looked up over the pixel's footprint (BAKED_FILTERED).
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
// The table as one mip-mapped 2-D layer per w sample (FloatTexture3D mipmapped): the pixel's footprint, a Gaussian in
// (u, v), becomes a mip level and two lookups along its long axis (mip_footprint.glsl), and the shader interpolates
// linearly between the two nearest w slices.
#define FILTERED 1
#include "/engine/mip_footprint.glsl"
uniform sampler2DArray bakedLayers;
// 1: surface pixels average over their footprint (PixelFilter.BOX); 0: their centre direction only
uniform float pixelFootprintScale;
// sigma_a of the light the table holds (isotropic, as at normal incidence: baked_lobes.frag)
uniform float tableLightSigmaRad;
MipFootprint footprint;

// Texels of the table per unit of u or v.
float texelsPerUv() {
    return 0.25 * (bakedSamples.x - 1.0);
}

// A BRDF-map pixel: a box of half-width halfWidth in u and v, variance halfWidth^2 / 3 per axis.
void setMapPixel(float halfWidth) {
    float h = halfWidth * texelsPerUv();
    footprint = mipFootprint(vec3(h * h / 3.0, 0.0, h * h / 3.0));
}

// A surface pixel: the Gaussian (J_x J_x^T + J_y J_y^T) / 12 of its (u, v) derivatives (lobes_footprint.glsl's
// setSurfacePixelUnder), plus what a light of sigma_a = sigmaRad adds to the table's light: LightSource.uvCovariance
// at omega_i, sigma_a^2 (cos^2 theta r r^T + e e^T), less the table's isotropic sigma_a^2 where positive (a
// narrower light than the table's is not sharpened).
void setSurfacePixelUnder(vec2 dUvDx, vec2 dUvDy, vec3 wi, float sigmaRad) {
    vec3 c = pixelFootprintScale * vec3(dUvDx.x * dUvDx.x + dUvDy.x * dUvDy.x, dUvDx.x * dUvDx.y
            + dUvDy.x * dUvDy.y, dUvDx.y * dUvDx.y + dUvDy.y * dUvDy.y) / 12.0;
    float sinTheta = length(wi.xy);
    vec2 r = sinTheta > 1e-6 ? wi.xy / sinTheta : vec2(1.0, 0.0);
    float table = tableLightSigmaRad * tableLightSigmaRad;
    float along = max(sigmaRad * sigmaRad * wi.z * wi.z - table, 0.0);
    float across = max(sigmaRad * sigmaRad - table, 0.0);
    c += along * vec3(r.x * r.x, r.x * r.y, r.y * r.y) + across * vec3(r.y * r.y, -r.x * r.y, r.x * r.x);
    footprint = mipFootprint(c * texelsPerUv() * texelsPerUv());
}

void setSurfacePixel(vec2 dUvDx, vec2 dUvDy, vec3 wi) {
    setSurfacePixelUnder(dUvDx, dUvDy, wi, tableLightSigmaRad);
}

vec3 spectralXyz(vec3 uvw) {
    vec2 tc = bakedTexcoord(uvw).xy;
    float slice = clamp((uvw.z + 2.0) * 0.5 * (bakedSamples.y - 1.0), 0.0, bakedSamples.y - 1.0);
    float below = min(floor(slice), bakedSamples.y - 2.0);
    vec3 a = textureFootprint(bakedLayers, tc, below, footprint).rgb;
    vec3 b = textureFootprint(bakedLayers, tc, below + 1.0, footprint).rgb;
    return mix(a, b, slice - below);
}
#else
vec3 spectralXyz(vec3 uvw) {
    return texture(bakedXyz, bakedTexcoord(uvw)).rgb;
}
#endif

#include "diffraction_main.glsl"
#endif
