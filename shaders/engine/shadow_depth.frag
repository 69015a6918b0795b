#version 330 core
// Depth pass of diffract.jrtr.ShadowMap: the depth buffer is the output; no colour is written.
void main() {
}
