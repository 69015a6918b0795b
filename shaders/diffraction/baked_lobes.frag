#version 330 core
// The bake pass of a BAKED table of the lobes method (BakedTable.bake with filtering): pixel (i, j) of an n x n
// viewport is the sample (u_i, v_j) of the slice w = bakeW (baked.frag's grid), the lobes method's spectral XYZ
// averaged over the sample's cell of the grid, a box of side 4 / (n - 1) in u and v, and over the light taken
// isotropic with sigma_a (setTableCell). Box averages of the cells add up to the integral of the BRDF, so the table
// keeps every order's energy at any resolution; baked.frag looks it up with mip levels over a pixel's footprint.
#define FILTERED 1
#include "lobes_spectrum.glsl"
#include "bake_sample.glsl"

uniform float bakeW;
out vec4 fragColor;

// Unreachable samples are 0, as in baked.frag (bakeSampleUnreachable).
void main() {
    vec3 uvw = bakeSampleUvw(bakeW);
    if (bakeSampleUnreachable(uvw)) {
        fragColor = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    setTableCell(2.0 / (bakedSamples.x - 1.0));
    vec3 xyz = spectralXyz(uvw);
    fragColor = vec4(xyz, spectrumTruncated() ? 0.0 : 1.0); // alpha 0: lobes left out (BakedTable counts them)
}
