// The baked table's samples and, with BAKED_FILTERED or ENVIRONMENT_TABLE, its lookup over a footprint: the lobes
// method's table (baked_lobes.frag) as one mip-mapped 2-D layer per w sample (FloatTexture3D mipmapped), spread by a
// Gaussian footprint in (u, v) through a mip level and two lookups along its long axis (mip_footprint.glsl), and
// interpolated linearly between the two nearest w slices. Included by baked.frag (the BAKED variant) and by
// lobes_spectrum.glsl for environment lights wider than the lobes method takes (ENVIRONMENT_TABLE).
#ifndef BAKED_TABLE_GLSL
#define BAKED_TABLE_GLSL

#include "bake_sample.glsl"

// Sample index t = (x - x_min) / (x_max - x_min) (n - 1) per axis; texel i's centre is at (i + 0.5) / n.
vec3 bakedTexcoord(vec3 uvw) {
    vec3 t = vec3((uvw.xy + 2.0) * 0.25 * (bakedSamples.x - 1.0), (uvw.z + 2.0) * 0.5 * (bakedSamples.y - 1.0));
    return (t + 0.5) / bakedSamples.xxy;
}

#if defined(BAKED_FILTERED) || defined(ENVIRONMENT_TABLE)
#include "/engine/mip_footprint.glsl"
#include "footprint_covariance.glsl"
uniform sampler2DArray bakedLayers;
// sigma_a of the light the table holds (isotropic, as at normal incidence: baked_lobes.frag)
uniform float tableLightSigmaRad;

// Texels of the table per unit of u or v.
float tableTexelsPerUv() {
    return 0.25 * (bakedSamples.x - 1.0);
}

// A BRDF-map pixel: a box of half-width halfWidth in u and v, variance halfWidth^2 / 3 per axis (texels^2).
vec3 tableMapPixelCovariance(float halfWidth) {
    float h = halfWidth * tableTexelsPerUv();
    return vec3(h * h / 3.0, 0.0, h * h / 3.0);
}

MipFootprint tableMapPixel(float halfWidth) {
    return mipFootprint(tableMapPixelCovariance(halfWidth));
}

// A surface pixel: the Gaussian (J_x J_x^T + J_y J_y^T) / 12 of its (u, v) derivatives times pixelScale (1 for a
// box pixel, 0 for a point: lobes_footprint.glsl's setSurfacePixelUnder), plus what a light of sigma_a = sigmaRad
// adds to the table's light: LightSource.uvCovariance at omega_i, sigma_a^2 (cos^2 theta r r^T + e e^T), less the
// table's isotropic sigma_a^2 where positive (a narrower light than the table's is not sharpened).
// (its covariance in texels^2)
vec3 tableSurfacePixelCovariance(vec2 dUvDx, vec2 dUvDy, vec3 wi, float sigmaRad, float pixelScale) {
    float table = tableLightSigmaRad * tableLightSigmaRad;
    vec3 c = pixelScale * pixelCovariance(dUvDx, dUvDy) + lightCovarianceAxes(wi,
            max(sigmaRad * sigmaRad * wi.z * wi.z - table, 0.0), max(sigmaRad * sigmaRad - table, 0.0));
    return c * tableTexelsPerUv() * tableTexelsPerUv();
}

MipFootprint tableSurfacePixel(vec2 dUvDx, vec2 dUvDy, vec3 wi, float sigmaRad, float pixelScale) {
    return mipFootprint(tableSurfacePixelCovariance(dUvDx, dUvDy, wi, sigmaRad, pixelScale));
}

// The w slice below w and the fraction of the way to the next one.
vec2 tableSlice(float w) {
    float slice = clamp((w + 2.0) * 0.5 * (bakedSamples.y - 1.0), 0.0, bakedSamples.y - 1.0);
    float below = min(floor(slice), bakedSamples.y - 2.0);
    return vec2(below, slice - below);
}

// Layers `s` at (u, v) between the two w slices of `slice` (tableSlice), spread by the footprint.
vec3 slicesAt(sampler2DArray s, vec2 uv, vec2 slice, MipFootprint footprint) {
    vec2 tc = bakedTexcoord(vec3(uv, 0.0)).xy;
    return mix(textureFootprint(s, tc, slice.x, footprint).rgb, textureFootprint(s, tc, slice.x + 1.0, footprint).rgb,
            slice.y);
}

// XYZ(u, v, w) of the table spread by the footprint.
vec3 tableXyz(vec3 uvw, MipFootprint footprint) {
    return slicesAt(bakedLayers, uvw.xy, tableSlice(uvw.z), footprint);
}
#endif

#endif
