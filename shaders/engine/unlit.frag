#version 330 core
// Minimal engine fragment shader: a uniform colour, or with OUTPUT_NORMAL defined the encoded world normal.
#include "common.glsl"

in vec3 worldNormal;

uniform vec4 color;

out vec4 fragColor;

void main() {
#ifdef OUTPUT_NORMAL
    fragColor = vec4(encodeNormal(worldNormal), 1.0);
#else
    fragColor = color;
#endif
}
