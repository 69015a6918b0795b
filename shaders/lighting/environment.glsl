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
// diffract.jrtr.ShadowMap: world -> [0, 1]^3 of the key light's depth map, raw depths compared here.
uniform sampler2D shadowMap;
uniform mat4 shadowMatrix;
uniform float shadowNormalOffset;     // world units: the lookup starts this far out along the normal (against acne)
uniform float shadowTexelWorld;       // world units across a texel of the map
uniform float shadowDepthRangeWorld;  // world units along the light per unit of stored depth
uniform float keyLightTanHalfAngle;   // tan of half the key light's angular diameter (0: a point light)

// Percentage-closer soft shadows (R. Fernando, "Percentage-Closer Soft Shadows", SIGGRAPH 2005 sketch) for a
// directional light of angular diameter D: a blocker edge a distance d above the receiver (along the light) hides
// the light's disc over a penumbra of radius d tan(D / 2) around the geometric edge, and the fraction of the disc
// left visible at a point is the fraction of a disc of that radius around it that no blocker covers. So: the
// blockers' mean depth within the cone towards the light, then percentage-closer filtering over that disc.
const int SHADOW_BLOCKER_TAPS = 16;
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

// The stored depth of a texel of a map of `size` texels; beyond the map nothing blocks (depth 1).
float storedDepth(ivec2 texel, ivec2 size) {
    if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, size))) {
        return 1.0;
    }
    return texelFetch(shadowMap, texel, 0).r;
}

// 1 where the receiver at `depth` is in front of what the map stores (GL_LEQUAL), bilinear over the four texels
// around st: the comparison a sampler2DShadow's linear filter makes.
float litFraction(vec2 st, float depth, ivec2 size) {
    vec2 f = st * vec2(size) - 0.5;
    ivec2 i = ivec2(floor(f));
    vec2 w = f - floor(f);
    float a = step(depth, storedDepth(i, size));
    float b = step(depth, storedDepth(i + ivec2(1, 0), size));
    float c = step(depth, storedDepth(i + ivec2(0, 1), size));
    float e = step(depth, storedDepth(i + ivec2(1, 1), size));
    return mix(mix(a, b, w.x), mix(c, e, w.x), w.y);
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
    float blockerSum = 0.0;
    int blockers = 0;
    for (int i = 0; i < SHADOW_BLOCKER_TAPS; i++) {
        vec2 o = vogelDisc(i, SHADOW_BLOCKER_TAPS) * searchTexels;
        float d = storedDepth(ivec2(floor(s.xy * size + o)), texels);
        if (d < s.z - slopePerTexel * length(o)) {
            blockerSum += d;
            blockers++;
        }
    }
    if (blockers == 0) {
        return 1.0;
    }
    if (blockers == SHADOW_BLOCKER_TAPS) {
        return 0.0; // the search disc, wider than the penumbra's, is covered: the umbra
    }
    float radiusTexels = clamp((s.z - blockerSum / float(blockers)) * texelsPerDepth, 1.0, SHADOW_MAX_RADIUS_TEXELS);
    float sum = 0.0;
    for (int i = 0; i < SHADOW_FILTER_TAPS; i++) {
        vec2 o = vogelDisc(i, SHADOW_FILTER_TAPS) * radiusTexels;
        sum += litFraction(s.xy + o / size, s.z - slopePerTexel * length(o), texels);
    }
    return sum / float(SHADOW_FILTER_TAPS);
}
#else
float keyLightVisibility(vec3 worldPosition, vec3 worldNormal, vec3 towardsLight) {
    return 1.0;
}
#endif
#endif
