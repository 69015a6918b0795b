#version 330 core
// 003 Algorithm 2: omega_i and omega_r in the vertex's tangent frame, and p = P C^-1 M p_obj. The tangent frame's
// x axis (T) runs along the height field's columns, y (B = N x T) along its rows, z is the normal, as in
// diffract.optics.patches.Direction.
in vec3 position;
in vec3 normal;
in vec3 tangent;
in vec2 texcoord;

uniform mat4 model;
uniform mat4 view;          // C^-1
uniform mat4 projection;    // P
uniform mat3 normalMatrix;  // inverse transpose of the model's 3x3 part
uniform vec3 cameraPosition;      // world space
uniform vec3 lightDirection[ENGINE_MAX_LIGHTS];   // world space, towards the light; [0] is used

// as engine/depth_prepass.vert computes it, so the shading pass's depth test keeps exactly the pre-pass's surface
invariant gl_Position;

out vec3 omegaITangent;
out vec3 toViewerTangent;
out vec2 surfaceTexcoord;
// world-space position and frame, for fragment shaders that rebuild the frame per fragment (surface_stage.glsl)
out vec3 surfaceWorldPosition;
out vec3 surfaceWorldNormal;
out vec3 surfaceWorldTangent;

// normalize() of a zero vector is undefined; degenerate frames give (0, 0, 0), which the fragment shader
// treats as below the horizon (black).
vec3 safeNormalizeVertex(vec3 v) {
    float len2 = dot(v, v);
    return len2 > 1e-30 ? v * inversesqrt(len2) : vec3(0.0);
}

// Components of v along T, B, N (Algorithm 2's projectVectorOnTo).
vec3 toTangentSpace(vec3 v, vec3 t, vec3 b, vec3 n) {
    return vec3(dot(v, t), dot(v, b), dot(v, n));
}

void main() {
    vec4 worldPosition = model * vec4(position, 1.0);
    vec3 n = safeNormalizeVertex(normalMatrix * normal);
    vec3 t = mat3(model) * tangent;
    // Gram-Schmidt: interpolated or sheared tangents need not be perpendicular to the normal
    t = safeNormalizeVertex(t - dot(t, n) * n);
    vec3 b = cross(n, t);
    omegaITangent = toTangentSpace(safeNormalizeVertex(lightDirection[0]), t, b, n);
    toViewerTangent = toTangentSpace(cameraPosition - worldPosition.xyz, t, b, n);
    surfaceTexcoord = texcoord;
    surfaceWorldPosition = worldPosition.xyz;
    surfaceWorldNormal = n;
    surfaceWorldTangent = t;
    gl_Position = projection * view * worldPosition;
}
