// Light from the environment and the key light's shadow, shared by the staged surface (diffraction) and the
// ground. Conventions of diffract.lighting: radiance in units of the key light, world frame with y up.
#ifndef ENVIRONMENT_GLSL
#define ENVIRONMENT_GLSL

#ifdef IRRADIANCE_SH
// ShIrradiance.shaderCoefficients: E(n) = c0 + c1 y + c2 z + c3 x + c4 xy + c5 yz + c6 (3 z^2 - 1) + c7 xz
// + c8 (x^2 - y^2), Ramamoorthi and Hanrahan 2001.
uniform vec3 irradianceSh[9];

vec3 environmentIrradiance(vec3 n) {
    vec3 e = irradianceSh[0] + irradianceSh[1] * n.y + irradianceSh[2] * n.z + irradianceSh[3] * n.x
            + irradianceSh[4] * n.x * n.y + irradianceSh[5] * n.y * n.z + irradianceSh[6] * (3.0 * n.z * n.z - 1.0)
            + irradianceSh[7] * n.x * n.z + irradianceSh[8] * (n.x * n.x - n.y * n.y);
    return max(e, vec3(0.0));
}
#else
vec3 environmentIrradiance(vec3 n) {
    return vec3(0.0);
}
#endif

#ifdef SHADOW_MAP
// diffract.jrtr.ShadowMap: world -> [0, 1]^3 of the key light's depth map, sampled with comparisons (GL_LEQUAL,
// bilinear); diffract.jrtr.textures.DepthBounds: (min, max) of its depths over blocks of 2^p texels at level p, level 0 the
// raw depths.
uniform sampler2DShadow shadowMap;
uniform sampler2D shadowDepthBounds;
uniform mat4 shadowMatrix;
uniform float shadowNormalOffset;     // world units: the lookup starts this far out along the normal (against acne)
uniform float shadowTexelWorld;       // world units across a texel of the map
uniform float shadowDepthRangeWorld;  // world units along the light per unit of stored depth
uniform float keyLightTanHalfAngle;   // tan of half the key light's angular diameter (0: a point light)

// SHADOW_TAPS_ONLY compares every tap, without the depth bounds' shortcuts, which give the same answer
// (ShadowBoundsTest holds them to it).
// Percentage-closer soft shadows (R. Fernando, "Percentage-Closer Soft Shadows", SIGGRAPH 2005 sketch) for a
// directional light of angular diameter D: a blocker edge a distance d above the receiver (along the light) hides
// the light's disc over a penumbra of radius d tan(D / 2) around the geometric edge, and the fraction of the disc
// left visible at a point is the fraction of a disc of that radius around it that no blocker covers. So: the
// blockers' mean depth within the cone towards the light, then percentage-closer filtering over that disc.
const int SHADOW_BLOCKER_TAPS = 8;
const int SHADOW_FILTER_TAPS = 48;
// The widest disc searched and filtered, texels: beyond it a penumbra is cut to this radius. The taps' count stays
// fixed, so a wide disc's taps lie several texels apart: the visibility then steps by 1 / SHADOW_FILTER_TAPS, finer
// than a display's 8 bits resolve along the gradient.
const float SHADOW_MAX_RADIUS_TEXELS = 256.0;
const float GOLDEN_ANGLE = 2.39996323;

// Vogel's spiral: tap i of n, spread evenly over the unit disc.
vec2 vogelDisc(int i, int n) {
    float r = sqrt((float(i) + 0.5) / float(n));
    float a = float(i) * GOLDEN_ANGLE;
    return r * vec2(cos(a), sin(a));
}

// The nearest stored depth in the block of 2^level texels holding a texel of a map of `size` texels; beyond the map
// nothing blocks (depth 1).
float nearestDepthAround(ivec2 texel, ivec2 size, int level) {
    if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, size))) {
        return 1.0;
    }
    return texelFetch(shadowDepthBounds, texel >> level, level).r;
}

// The level of the depth bounds the blocker search reads for a search disc of `radiusTexels`: blocks a quarter of the
// radius wide (the 8 taps lie about 0.6 radii apart), so that a wide search reads a small level that stays in the
// cache rather than texels scattered over the whole map, and a narrow one reads the texels themselves.
int searchLevel(float radiusTexels) {
    return clamp(int(floor(log2(radiusTexels / 4.0))), 0, 5);
}

// 1 where the receiver at `depth` is at or in front of what the map stores, bilinear over the four texels around
// st (the sampler's comparison; outside the map its border, depth 1, blocks nothing).
float litFraction(vec2 st, float depth) {
    return texture(shadowMap, vec3(st, depth));
}

// (min, max) of the stored depths over the texels [lo, hi] (both corners inclusive, per axis) of a map of `size`
// texels, read from the bounds of the at most 2 x 2 blocks of the finest level whose blocks are as wide as the
// range; texels outside the map are left out (they store 1 and block nothing).
vec2 depthBoundsOver(ivec2 lo, ivec2 hi, ivec2 size) {
    lo = clamp(lo, ivec2(0), size - 1);
    hi = clamp(hi, ivec2(0), size - 1);
    int width = max(hi.x - lo.x, hi.y - lo.y) + 1;
    int levels = int(log2(float(textureSize(shadowDepthBounds, 0).x)) + 0.5) + 1; // sides 2^(levels-1) .. 1
    int p = min(int(ceil(log2(float(width)))), levels - 1);
    ivec2 a = lo >> p;
    ivec2 b = hi >> p;
    vec2 b00 = texelFetch(shadowDepthBounds, a, p).rg;
    vec2 b10 = texelFetch(shadowDepthBounds, ivec2(b.x, a.y), p).rg;
    vec2 b01 = texelFetch(shadowDepthBounds, ivec2(a.x, b.y), p).rg;
    vec2 b11 = texelFetch(shadowDepthBounds, b, p).rg;
    return vec2(min(min(b00.x, b10.x), min(b01.x, b11.x)), max(max(b00.y, b10.y), max(b01.y, b11.y)));
}

// Whether a disc of taps around texel position c (in texels) of radius r is settled by the depth bounds of the
// texels it can touch, for a receiver at `depth` whose comparisons move by at most `slack` across the disc:
// 1 when no stored depth there lies in front of the receiver (every tap lit), 0 when all lie in front of it by more
// than the slack and the disc is inside the map (every tap blocked), -1 when the taps must be compared one by one.
// The taps then give exactly this answer: the test only skips their work.
float settledByBounds(vec2 c, float r, float depth, float slack, ivec2 size) {
    ivec2 lo = ivec2(floor(c - r)) - 1;
    ivec2 hi = ivec2(floor(c + r)) + 1;
    vec2 bounds = depthBoundsOver(lo, hi, size);
    if (bounds.x >= depth) {
        return 1.0;
    }
    if (all(greaterThanEqual(lo, ivec2(0))) && all(lessThan(hi, size)) && bounds.y < depth - slack) {
        return 0.0;
    }
    return -1.0;
}

// The fraction of the key light reaching a point with normal worldNormal, the light towards towardsLight.
float keyLightVisibility(vec3 worldPosition, vec3 worldNormal, vec3 towardsLight) {
    vec4 p = shadowMatrix * vec4(worldPosition + shadowNormalOffset * worldNormal, 1.0);
    vec3 s = p.xyz / p.w;
    if (s.z >= 1.0) {
        return 1.0;
    }
    ivec2 texels = textureSize(shadowMap, 0);
    vec2 size = vec2(texels);
    // a receiver tilted by theta against the light lies r tan(theta) deeper r world units away: each tap's
    // comparison moves by that much (in stored depth per texel), so a wide disc does not shadow its own surface
    float c = clamp(dot(normalize(worldNormal), normalize(towardsLight)), 0.1, 1.0);
    float slopePerTexel = sqrt(1.0 - c * c) / c * shadowTexelWorld / shadowDepthRangeWorld;
    float texelsPerDepth = shadowDepthRangeWorld * keyLightTanHalfAngle / shadowTexelWorld;
    // blockers: anywhere between the light's side of the map and the receiver, within the cone towards the light
    float searchTexels = clamp(s.z * texelsPerDepth, 1.0, SHADOW_MAX_RADIUS_TEXELS);
#ifndef SHADOW_TAPS_ONLY
    // the whole search disc beyond the map, where nothing blocks: lit
    vec2 beyond = max(-s.xy, s.xy - 1.0) * size;
    if (max(beyond.x, beyond.y) > searchTexels + 1.0) {
        return 1.0;
    }
    // nothing in front of the receiver anywhere in the search disc: lit, as the search would find
    if (depthBoundsOver(ivec2(floor(s.xy * size - searchTexels)), ivec2(floor(s.xy * size + searchTexels)), texels).x
            >= s.z) {
        return 1.0;
    }
#endif
    // the blockers' mean depth (PCSS's estimate of their distance), from the nearest depth of the block under each
    // tap: within a wide search a block is a few texels, and its nearest depth tells whether it holds a blocker
    float blockerSum = 0.0;
    int blockers = 0;
    int level = searchLevel(searchTexels);
    for (int i = 0; i < SHADOW_BLOCKER_TAPS; i++) {
        vec2 o = vogelDisc(i, SHADOW_BLOCKER_TAPS) * searchTexels;
        float d = nearestDepthAround(ivec2(floor(s.xy * size + o)), texels, level);
        if (d < s.z - slopePerTexel * length(o)) {
            blockerSum += d;
            blockers++;
        }
    }
    if (blockers == 0) {
        return 1.0;
    }
    // Every tap finding a blocker is no proof of umbra when the taps read blocks (a block with one blocking texel
    // counts): the filter below decides, and settles a true umbra at once by the bounds.
    if (level == 0 && blockers == SHADOW_BLOCKER_TAPS) {
        return 0.0; // the search disc, wider than the penumbra's, is covered: the umbra
    }
    float radiusTexels = clamp((s.z - blockerSum / float(blockers)) * texelsPerDepth, 1.0, SHADOW_MAX_RADIUS_TEXELS);
    // each tap's bilinear comparison reads the texels within one of its position, its depth moves by at most
    // slopePerTexel x radiusTexels: the whole filter disc lit or blocked is settled by the bounds
#ifndef SHADOW_TAPS_ONLY
    float settled = settledByBounds(s.xy * size - 0.5, radiusTexels, s.z, slopePerTexel * radiusTexels, texels);
    if (settled >= 0.0) {
        return settled;
    }
#endif
    float sum = 0.0;
    for (int i = 0; i < SHADOW_FILTER_TAPS; i++) {
        vec2 o = vogelDisc(i, SHADOW_FILTER_TAPS) * radiusTexels;
        sum += litFraction(s.xy + o / size, s.z - slopePerTexel * length(o));
    }
    return sum / float(SHADOW_FILTER_TAPS);
}
#else
float keyLightVisibility(vec3 worldPosition, vec3 worldNormal, vec3 towardsLight) {
    return 1.0;
}
#endif
#endif
