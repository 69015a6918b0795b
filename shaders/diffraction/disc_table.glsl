// A wide disc light on a surface (DISC_TABLE; diffract.render.DiscTable): the table spread in advance by round discs
// of radius sin R c_k, one member per c_k (DISC_TABLE_COS, ascending from c_0 = 0, the point table itself), read with
// the rest of the pixel's ellipse as a Gaussian footprint: one footprint lookup (two w slices) where integrating the
// disc over the table's rows reads tens. The ellipse (disc_ellipse.glsl) has a = sin R along e and b = a cos theta_i
// along r; the member of the largest c_k <= cos theta_i leaves (a^2 / 4)(1 - c_k^2) along e and
// (a^2 / 4)(cos^2 theta_i - c_k^2) along r, which the footprint adds (below the first disc member, the point member
// with the whole disc). Over the upper DISC_TABLE_BLEND of the interval to the next member, the two members are
// blended. C, S and w are the light centre's, as for a Gaussian light. Every pixel reads the members' texture alone:
// a software rasteriser runs every branch any of a pixel block's lanes takes. Included by baked_disc.glsl.
#ifndef DISC_TABLE_GLSL
#define DISC_TABLE_GLSL

uniform sampler2DArray discTable;
uniform float discTableSide; // (u, v) samples per axis of each member; its w slices are the table's
const float discTableCos[DISC_TABLE_MEMBERS] = DISC_TABLE_COS;

// The disc's ellipse read from member k (c_k = ck), with the pixel's footprint (covariance in texels^2 of the
// table's level 0), at cos theta_i = c.
vec3 discMemberXyz(int k, float ck, DiscEllipse el, vec2 centre, float w, vec3 footprintTexels, float c) {
    float a2 = 0.25 * el.axes.x * el.axes.x;
    vec2 e = el.e;
    vec2 r = el.r;
    vec3 rest = a2 * (1.0 - ck * ck) * vec3(e.x * e.x, e.x * e.y, e.y * e.y)
            + a2 * max(c * c - ck * ck, 0.0) * vec3(r.x * r.x, r.x * r.y, r.y * r.y);
    float spreadPerUv = 0.25 * (discTableSide - 1.0);
    float scale = spreadPerUv / tableTexelsPerUv();
    MipFootprint m = mipFootprint(footprintTexels * scale * scale + rest * spreadPerUv * spreadPerUv);
    vec2 tc = ((centre + 2.0) * spreadPerUv + 0.5) / discTableSide;
    vec2 slice = tableSlice(w);
    float layer = float(k) * bakedSamples.y + slice.x;
    return mix(textureFootprint(discTable, tc, layer, m).rgb, textureFootprint(discTable, tc, layer + 1.0, m).rgb,
            slice.y);
}

// The disc's average of the table for the pixel of setDisc (its centre's C, S and w), with the pixel's footprint.
// Both members of a blend are read by every pixel (their lookups run for the block's lanes whichever blend).
vec3 spreadDiscXyz(DiscEllipse el, vec2 centre, vec3 footprintTexels) {
    float c = clamp(discWi.z, 0.0, 1.0);
    float w = -(discWi.z + discWr.z);
    int k = 0;
    for (int m = 1; m < DISC_TABLE_MEMBERS; m++) {
        if (discTableCos[m] <= c) {
            k = m;
        }
    }
    int next = min(k + 1, DISC_TABLE_MEMBERS - 1);
    float ck = discTableCos[k];
    float cNext = discTableCos[next];
    float blend = next > k ? smoothstep(1.0 - DISC_TABLE_BLEND, 1.0, (c - ck) / (cNext - ck)) : 0.0;
    return mix(discMemberXyz(k, ck, el, centre, w, footprintTexels, c),
            discMemberXyz(next, cNext, el, centre, w, footprintTexels, c), blend);
}

#endif
