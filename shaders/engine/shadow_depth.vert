#version 330 core
// Depth pass of diffract.jrtr.ShadowMap: positions through the light's orthographic view, nothing else.
in vec3 position;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

void main() {
    gl_Position = projection * view * model * vec4(position, 1.0);
}
