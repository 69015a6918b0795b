#version 330 core
// Minimal engine vertex shader: transforms positions, passes the world-space normal on.

in vec3 position;
in vec3 normal;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform mat3 normalMatrix;

out vec3 worldNormal;

// as engine/depth_prepass.vert computes it, so the shading pass's depth test keeps exactly the pre-pass's surface
invariant gl_Position;

void main() {
    worldNormal = normalMatrix * normal;
    vec4 worldPosition = model * vec4(position, 1.0);
    gl_Position = projection * view * worldPosition;
}
