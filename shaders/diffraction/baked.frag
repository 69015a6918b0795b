#version 330 core
#if defined(SKY_TABLE) && defined(GL_ARB_derivative_control)
#extension GL_ARB_derivative_control : enable
#endif
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
#include "baked_table.glsl"

#ifdef BAKE
// ---- The bake pass: pixel (i, j) of an n x n viewport is the sample (u_i, v_j) of the slice w = bakeW.
uniform float bakeW;
out vec4 fragColor;

void main() {
    vec3 uvw = bakeSampleUvw(bakeW);
    if (bakeSampleUnreachable(uvw)) {
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

#ifdef BAKED_FILTERED
// The lobes method's table looked up over the pixel's footprint (baked_table.glsl); under a disc light the disc is
// integrated over the running sums of the table's rows (baked_disc.glsl).
#define FILTERED 1
// 1: surface pixels average over their footprint (PixelFilter.BOX); 0: their centre direction only
uniform float pixelFootprintScale;
vec3 footprintCovariance; // texels^2 of the table's level 0
MipFootprint footprint;
float mapPixelHalfWidthUv = 0.0; // a BRDF map's pixel: half the side of its square box in (u, v); 0 on a surface

void setMapPixel(float halfWidth) {
    mapPixelHalfWidthUv = halfWidth;
    footprintCovariance = tableMapPixelCovariance(halfWidth);
    footprint = mipFootprint(footprintCovariance);
}

void setSurfacePixelUnder(vec2 dUvDx, vec2 dUvDy, vec3 wi, float sigmaRad) {
    footprintCovariance = tableSurfacePixelCovariance(dUvDx, dUvDy, wi, sigmaRad, pixelFootprintScale);
    footprint = mipFootprint(footprintCovariance);
}

void setSurfacePixel(vec2 dUvDx, vec2 dUvDy, vec3 wi) {
    setSurfacePixelUnder(dUvDx, dUvDy, wi, tableLightSigmaRad);
}

#ifdef BAKED_DISC
#include "baked_disc.glsl"

#if defined(DISC_TABLE) && (!defined(STAGE) || !defined(ENVIRONMENT_LIGHTS) || defined(SKY_TABLE))
// Only the disc reads the table here (a stage's environment lights, if any, read their own spread tables), and a
// spread table's disc is never a point (discOn): the point lookup is left out rather than run beside the disc's for
// every pixel, as a software rasteriser runs both sides of a choice.
vec3 spectralXyz(vec3 uvw) {
    return discTableXyz(footprintCovariance);
}
#else
vec3 spectralXyz(vec3 uvw) {
    return discOn ? discTableXyz(footprintCovariance) : tableXyz(uvw, footprint);
}
#endif
#else
vec3 spectralXyz(vec3 uvw) {
    return tableXyz(uvw, footprint);
}
#endif
#else
vec3 spectralXyz(vec3 uvw) {
    return texture(bakedXyz, bakedTexcoord(uvw)).rgb;
}
#endif

#include "diffraction_main.glsl"
#endif
