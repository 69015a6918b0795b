#version 330 core
// Depth pre-pass of diffract.jrtr.GLRenderContext: the materials' own position expression, declared invariant in
// both, so that the shading pass's depths equal these exactly and its GL_LEQUAL test keeps the nearest surface only.
in vec3 position;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

invariant gl_Position;

void main() {
    vec4 worldPosition = model * vec4(position, 1.0);
    gl_Position = projection * view * worldPosition;
}
