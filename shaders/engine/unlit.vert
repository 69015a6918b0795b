#version 330 core
// Minimal engine vertex shader: transforms positions, passes the world-space normal on.

in vec3 position;
in vec3 normal;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform mat3 normalMatrix;

out vec3 worldNormal;

void main() {
    worldNormal = normalMatrix * normal;
    gl_Position = projection * view * model * vec4(position, 1.0);
}
