#version 330 core
// The ground under the snake: world positions for lighting, shadow and mottling.
in vec3 position;
in vec3 normal;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

out vec3 groundWorldPosition;

// as engine/depth_prepass.vert computes it, so the shading pass's depth test keeps exactly the pre-pass's surface
invariant gl_Position;

void main() {
    vec4 world = model * vec4(position, 1.0);
    groundWorldPosition = world.xyz;
    gl_Position = projection * view * world;
}
