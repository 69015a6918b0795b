#version 330 core
// Depth passes (diffract.jrtr.ShadowMap's, GLRenderContext's pre-pass): the depth buffer is the output; no colour
// is written.
void main() {
}
