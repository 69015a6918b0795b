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
// diffract.jrtr.ShadowMap: world -> [0, 1]^3 of the key light's depth map; the texture unit compares depths.
uniform sampler2DShadow shadowMap;
uniform mat4 shadowMatrix;
uniform float shadowNormalOffset; // world units: the lookup starts this far out along the normal (against acne)

// The fraction of the key light reaching a point: 5 percentage-closer taps of 2 x 2 each, a texel apart.
float keyLightVisibility(vec3 worldPosition, vec3 worldNormal) {
    vec4 p = shadowMatrix * vec4(worldPosition + shadowNormalOffset * worldNormal, 1.0);
    vec3 s = p.xyz / p.w;
    if (s.z >= 1.0) {
        return 1.0;
    }
    vec2 texel = 1.0 / vec2(textureSize(shadowMap, 0));
    float sum = texture(shadowMap, s);
    sum += texture(shadowMap, s + vec3(texel.x, texel.y, 0.0));
    sum += texture(shadowMap, s + vec3(-texel.x, texel.y, 0.0));
    sum += texture(shadowMap, s + vec3(texel.x, -texel.y, 0.0));
    sum += texture(shadowMap, s + vec3(-texel.x, -texel.y, 0.0));
    return sum / 5.0;
}
#else
float keyLightVisibility(vec3 worldPosition, vec3 worldNormal) {
    return 1.0;
}
#endif
#endif
