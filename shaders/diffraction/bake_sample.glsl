// The baked table's grid (BakedGrid) and the sample a bake pass's pixel stands for: shared by the table's lookup
// (baked_table.glsl) and both bake passes (baked.frag, baked_lobes.frag).
#ifndef BAKE_SAMPLE_GLSL
#define BAKE_SAMPLE_GLSL

// Samples of the table along u and along v (.x) and along w (.y): sample i of n sits at -2 + 4 i / (n - 1)
// (u, v) and -2 + 2 i / (n - 1) (w), both ends included (BakedGrid.uv, BakedGrid.w).
uniform vec2 bakedSamples;

// The bake passes (baked.frag, baked_lobes.frag): pixel (i, j) of an n x n viewport is the sample (u_i, v_j) of
// the slice w = bakeW.
vec3 bakeSampleUvw(float bakeW) {
    vec2 ij = floor(gl_FragCoord.xy);
    return vec3(-2.0 + 4.0 * ij / (bakedSamples.x - 1.0), bakeW);
}

// Only |(u, v, w)| = |omega_i + omega_r| <= 2 is reachable (about half of the box): a sample farther than one cell
// diagonal beyond it is never read by a trilinear lookup of a reachable point, and is baked as 0 at no cost.
bool bakeSampleUnreachable(vec3 uvw) {
    float cellDiagonal = length(vec3(4.0 / (bakedSamples.x - 1.0), 4.0 / (bakedSamples.x - 1.0),
                                     2.0 / (bakedSamples.y - 1.0)));
    return length(uvw) > 2.0 + cellDiagonal;
}

#endif
