// Small helpers shared by the engine's debug shaders; also what the #include tests exercise.
#ifndef ENGINE_COMMON_GLSL
#define ENGINE_COMMON_GLSL

// Maps a unit normal's components from [-1, 1] to displayable [0, 1].
vec3 encodeNormal(vec3 n) {
    return normalize(n) * 0.5 + 0.5;
}

#endif
