#version 330 core
// The ground (the ground material of diffract.render.StageResources): a Lambertian plane facing +y, its albedo
// mottled by value noise, lit by the key light (irradiance 1, shadowed) and the environment's diffuse irradiance,
// tone mapped as the surface is. Radiance = albedo x irradiance, in the units of the diffraction shaders' pigment term.
#include "environment.glsl"
#include "tone_mapping.glsl"
#include "/engine/srgb.glsl"

in vec3 groundWorldPosition;

uniform vec3 lightDirection[ENGINE_MAX_LIGHTS];  // engine: towards the key light, world
uniform vec3 albedoLinear;       // linear sRGB
uniform float mottle;            // relative amplitude of the albedo's variation, 0..1
uniform float mottleScale;       // noise cells per world unit

out vec4 fragColor;

float hash2(vec2 p) {
    return fract(sin(dot(p, vec2(127.1, 311.7))) * 43758.5453);
}

float valueNoise(vec2 p) {
    vec2 i = floor(p);
    vec2 f = fract(p);
    f = f * f * (3.0 - 2.0 * f);
    return mix(mix(hash2(i), hash2(i + vec2(1.0, 0.0)), f.x), mix(hash2(i + vec2(0.0, 1.0)), hash2(i + vec2(1.0)), f.x), f.y);
}

void main() {
    vec3 n = vec3(0.0, 1.0, 0.0);
    vec2 p = groundWorldPosition.xz * mottleScale;
    float noise = 0.6 * valueNoise(p) + 0.3 * valueNoise(p * 3.1) + 0.1 * valueNoise(p * 9.7);
    vec3 albedo = albedoLinear * (1.0 + mottle * (2.0 * noise - 1.0));
    float cosKey = max(dot(normalize(lightDirection[0]), n), 0.0);
    vec3 irradiance = vec3(cosKey * keyLightVisibility(groundWorldPosition, n, lightDirection[0]))
            + environmentIrradiance(n);
    vec3 c = toneMap(albedo * irradiance);
#ifdef LINEAR_OUTPUT
    fragColor = vec4(c, 1.0); // FrameOutput.LINEAR: linear light, as the surface's
#else
    fragColor = vec4(srgbEncode(c), 1.0);
#endif
}
