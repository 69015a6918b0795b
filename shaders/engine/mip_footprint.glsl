// A lookup of a mip-mapped texture (GL_LINEAR_MIPMAP_LINEAR, 2 x 2 box levels) that spreads the texture by a given
// Gaussian footprint, its covariance in texels^2 of level 0. GL's own level choice (textureGrad) takes the longer
// gradient for a box of that width and then blurs it again by the bilinear tent of the level's cells: a spread
// sqrt(3) times wider than the box. Here the level is solved for the variance, and an elongated footprint takes two
// lookups along its long axis instead of a wider level.
#ifndef ENGINE_MIP_FOOTPRINT_GLSL
#define ENGINE_MIP_FOOTPRINT_GLSL

// The level whose lookup spreads a point with variance varianceTexels (per axis), averaged over where the point
// falls in the level's cells: level k blends a box of 2^k texels with its bilinear tent, variance 4^k / 12 + 4^k / 6
// = 4^k / 4, and level k + f blends levels k and k + 1, variance 4^k (1 + 3 f) / 4; solved for k and f. Below 1/4
// (level 0's own spread) it is level 0.
float lodForVariance(float varianceTexels) {
    float t = max(4.0 * varianceTexels, 1.0);
    float k = floor(0.5 * log2(t));
    return k + (t / exp2(2.0 * k) - 1.0) / 3.0;
}

// A footprint as a level and a tap offset: the covariance (xx, xy, yy) splits into its smaller eigenvalue, isotropic,
// from the level, and the rest, (lambda_max - lambda_min) e e^T along the long axis e, from two lookups at +-offset
// (two points at +-a have variance a^2).
struct MipFootprint {
    float lod;
    vec2 offsetTexels;
};

MipFootprint mipFootprint(vec3 covarianceTexels) {
    vec3 c = covarianceTexels;
    float mean = 0.5 * (c.x + c.z);
    float halfSpread = sqrt(0.25 * (c.x - c.z) * (c.x - c.z) + c.y * c.y);
    vec2 longAxis = abs(c.y) > 1e-30 ? normalize(vec2(c.y, mean + halfSpread - c.x))
            : (c.x >= c.z ? vec2(1.0, 0.0) : vec2(0.0, 1.0));
    MipFootprint m;
    m.lod = lodForVariance(mean - halfSpread);
    m.offsetTexels = longAxis * sqrt(2.0 * halfSpread);
    return m;
}

// The texture at texcoord tc of layer `layer`, spread by the footprint. An isotropic footprint's two lookups
// coincide and average to the one exactly; they are not skipped by a branch, which a software rasteriser would run
// beside the two lookups wherever one lane of a pixel block is anisotropic.
vec4 textureFootprint(sampler2DArray s, vec2 tc, float layer, MipFootprint m) {
    vec2 offset = m.offsetTexels / vec2(textureSize(s, 0).xy);
    return 0.5 * (textureLod(s, vec3(tc + offset, layer), m.lod) + textureLod(s, vec3(tc - offset, layer), m.lod));
}

#endif
