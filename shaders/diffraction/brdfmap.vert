#version 330 core
// BRDF maps: a full-screen quad (Shapes.fullScreenQuad, [-1, 1]^2) straight into clip space. The fragment
// shader derives omega_r from gl_FragCoord exactly as BrdfMap does; omega_i is a uniform.
in vec3 position;

void main() {
    gl_Position = vec4(position.xy, 0.0, 1.0);
}
