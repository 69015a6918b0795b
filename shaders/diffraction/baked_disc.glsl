// The baked table of the lobes method under a disc light (BAKED_DISC; BakedDisc, docs/measurements/filtering.md section 8): the
// table (bakedLayers) holds the point light's cell averages and bakedRowSums the running sums of its rows along u
// (BakedDisc.rowSums: at sample i the integral of the table from u_min to u_i, linear between samples). A lookup
// integrates the disc itself: the ellipse its directions d form in (u, v) = -d.xy - omega_r.xy (DiscFootprint: centre
// -cos R omega_i.xy - omega_r.xy, semi-axis a = sin R across the plane of incidence, b = sin R cos theta_i in it),
// cut into rows along v and each row into pieces along u; a piece's integral is the difference of two running sums,
// weighted by the density 1 / (Omega d_z), the gain factor and shadowing relative to the light's centre and the w of
// its centre direction. Included by baked.frag after baked_table.glsl.
// DISC_ROWS_MAX, DISC_MIN_ROWS, DISC_FINE_ROWS_MAX, DISC_PIECES_MAX, DISC_PIECE_UV, DISC_TABLE_GAUSSIAN_BELOW,
// DISC_TABLE_EDGE_ABOVE, DISC_TABLE_BOX_BELOW, DISC_BOX_NODES_MAX, DISC_BOX_NODE_TEXELS: BakedDisc's constants,
// defined by DiffractionShaders.
#ifndef BAKED_DISC_GLSL
#define BAKED_DISC_GLSL

#include "disc_ellipse.glsl"

uniform sampler2DArray bakedRowSums;
uniform float lightHalfAngleRad;
bool discOn = false; // false for lights other than the settings' disc (a stage's environment lights)
vec3 discWi;
vec3 discWr;
float discCentreGain;
#ifdef DISC_TABLE
#include "disc_table.glsl"
#endif

// The pixel at omega_r under the disc about omega_i (diffraction_main.glsl and surface_stage.glsl call it).
void setDisc(vec3 wi, vec3 wr) {
    discWi = wi;
    discWr = wr;
    discCentreGain = gainTimesShadowing(wi, wr);
    discOn = lightHalfAngleRad > 0.0;
}

// The table integrated along u from u0 to u1 on the row at v, at w.
vec3 pieceIntegral(float u0, float u1, float v, float w, MipFootprint m) {
    vec2 slice = tableSlice(w);
    return slicesAt(bakedRowSums, vec2(u1, v), slice, m) - slicesAt(bakedRowSums, vec2(u0, v), slice, m);
}

#ifdef BRDF_MAP
// The table integrated along u up to u on the row at v, between the w slices of `slice`, at level 0, exact for the
// table held constant on its cells: the running sums are held at the samples' centres, where they bend, so their
// interpolant moves up to a quarter of a cell's content across the cell; half a sample below u, the running sum
// plus half a sample of the table is the integral up to the cell's upper edge, which is linear between the edges.
vec3 rowIntegralAt(float u, float v, vec2 slice) {
    MipFootprint m = MipFootprint(0.0, vec2(0.0));
    float halfSample = 0.5 / tableTexelsPerUv();
    vec2 at = vec2(u - halfSample, v);
    return slicesAt(bakedRowSums, at, slice, m) + halfSample * slicesAt(bakedLayers, at, slice, m);
}

// The table integrated along u from u0 to u1 on the row at v, at w, averaged over every shift s in [-h, h] of the
// piece (a map pixel's box along u): the midpoint rule over `nodes` shifts.
vec3 pieceIntegralOverBox(float u0, float u1, float h, int nodes, float v, float w) {
    vec2 slice = tableSlice(w);
    vec3 sum = vec3(0.0);
    for (int q = 0; q < DISC_BOX_NODES_MAX; q++) {
        if (q >= nodes) {
            break;
        }
        float s = h * (2.0 * (float(q) + 0.5) / float(nodes) - 1.0);
        sum += rowIntegralAt(u1 + s, v, slice) - rowIntegralAt(u0 + s, v, slice);
    }
    return sum / float(nodes);
}
#endif

// The disc's ellipse in (u, v) for the pixel of setDisc (disc_ellipse.glsl), with its centre, its reach along v, the
// half-width of its row through the centre and how that row's centre moves along u per unit of v.
struct DiscRows {
    DiscEllipse ellipse;
    vec2 centre;
    float reachV;
    float halfWidth0;
    float slope;
    float area; // pi a b
    float minorAxis; // b, at least 1e-6
    int pieces;
};

DiscRows discRows() {
    DiscEllipse el = discEllipse(discWi, lightHalfAngleRad);
    vec2 e = el.e;
    vec2 r = el.r;
    float a = el.axes.x;
    float b = max(el.axes.y, 1e-6);
    // the ellipse q^T M^-1 q <= 1 with M = a^2 e e^T + b^2 r r^T
    float mUv = a * a * e.x * e.y + b * b * r.x * r.y;
    float mVv = a * a * e.y * e.y + b * b * r.y * r.y;
    DiscRows d;
    d.ellipse = el;
    d.centre = -discWi.xy - discWr.xy + el.centreOffset;
    d.reachV = sqrt(mVv);
    d.halfWidth0 = a * b / d.reachV;
    d.slope = mUv / mVv;
    d.area = 3.14159265 * a * b;
    d.minorAxis = b;
    d.pieces = clamp(int(ceil(2.0 * d.halfWidth0 / DISC_PIECE_UV)), 1, DISC_PIECES_MAX);
    return d;
}

// The row of the ellipse at v = centre.v + y as (v, where its first piece starts, a piece's width); its width is
// added to `width`.
vec3 discRowAt(DiscRows d, float y, inout float width) {
    float halfWidth = d.halfWidth0 * sqrt(max(1.0 - y * y / (d.reachV * d.reachV), 0.0));
    width += 2.0 * halfWidth;
    return vec3(d.centre.y + y, d.centre.x + d.slope * y - halfWidth, 2.0 * halfWidth / float(d.pieces));
}

// The direction through (u, v): its density and gain relative to the light's centre, and its w; a weight of 0 below
// the horizon, where none arrives.
vec2 discPieceWeight(DiscRows d, float u, float v) {
    vec2 dir = -vec2(u, v) - discWr.xy;
    float dz2 = 1.0 - dot(dir, dir);
    if (!(dz2 > 0.0)) {
        return vec2(0.0);
    }
    float dz = sqrt(dz2);
    return vec2(gainTimesShadowing(vec3(dir, dz), discWr) / (discCentreGain * d.ellipse.solidAngle * dz),
            -(dz + discWr.z));
}

// Piece [u0, u1] of the row at v, at w: its integral, or with nodes > 0 (a map pixel's box of half-width h) its
// integral averaged over the box: a shift (s, t) of the pixel moves the ellipse by -(s, t) in (u, v) and leaves the
// piece's direction as it is, so the piece is read at v - t for each of `nodes` shifts t and over the shifts s
// (pieceIntegralOverBox). Callers pass nodes = 0 as a constant where there is no box, which the compiler folds away.
vec3 discPieceIntegral(float u0, float u1, float v, float w, MipFootprint m, float h, int nodes) {
#ifdef BRDF_MAP
    if (nodes > 0) {
        vec3 shifted = vec3(0.0);
        for (int n = 0; n < DISC_BOX_NODES_MAX; n++) {
            if (n >= nodes) {
                break;
            }
            float t = h * (2.0 * (float(n) + 0.5) / float(nodes) - 1.0);
            shifted += pieceIntegralOverBox(u0, u1, h, nodes, v - t, w);
        }
        return shifted / float(nodes);
    }
#endif
    return pieceIntegral(u0, u1, v, w, m);
}

// The row of the ellipse at y: its pieces' integrals (discPieceIntegral), each times its direction's density and
// gain relative to the light's centre, at its direction's w; its width is added to `width` once.
vec3 discRow(DiscRows d, float y, MipFootprint m, float h, int nodes, inout float width) {
    vec3 row = discRowAt(d, y, width);
    vec3 sum = vec3(0.0);
    for (int j = 0; j < DISC_PIECES_MAX; j++) {
        if (j >= d.pieces) {
            break;
        }
        float u0 = row.y + float(j) * row.z;
        vec2 weight = discPieceWeight(d, u0 + 0.5 * row.z, row.x);
        if (weight.x != 0.0) {
            sum += weight.x * discPieceIntegral(u0, u0 + row.z, row.x, weight.y, m, h, nodes);
        }
    }
    return sum;
}

// The disc's average of the table times the density and the gain relative to the light's centre, for the pixel of
// setDisc, with the pixel's footprint (covariance in texels^2 of level 0). As DiscFootprint, a disc whose minor
// semi-axis b is narrow next to the footprint's spread s is its Gaussian of equal covariance (a^2 / 4 along e,
// b^2 / 4 along r, added to the footprint; C, S and w at the light's centre), a wide one is cut into rows, blended
// for b / s between DISC_TABLE_GAUSSIAN_BELOW and DISC_TABLE_EDGE_ABOVE. The rows are a table sample apart (at least
// DISC_MIN_ROWS, at most DISC_ROWS_MAX), each taken at its centre (the midpoint rule across v). A row's running sums
// read at a coarse mip level hold the table's integral but not where within a level's texel it lies, so a row
// shorter than the level's texels would place it by up to half a texel: narrow discs take the Gaussian instead.
vec3 discTableXyz(vec3 footprintTexels) {
    if (discCentreGain <= 0.0) {
        return vec3(0.0);
    }
    DiscRows d = discRows();
#ifdef DISC_TABLE
    // a wide disc on a surface: the table spread by it (disc_table.glsl)
    return spreadDiscXyz(d.ellipse, d.centre, footprintTexels);
#endif
    float texelsPerUv = tableTexelsPerUv();
    vec2 r = d.ellipse.r;
    float spreadR = sqrt(max(footprintTexels.x * r.x * r.x + 2.0 * footprintTexels.y * r.x * r.y
            + footprintTexels.z * r.y * r.y, 0.25)) / texelsPerUv;
    float edgeWeight = smoothstep(DISC_TABLE_GAUSSIAN_BELOW, DISC_TABLE_EDGE_ABOVE, d.minorAxis / spreadR);
    vec3 xyz = vec3(0.0);
    if (edgeWeight < 1.0) {
        vec3 disc = discEllipseCovariance(d.ellipse) * texelsPerUv * texelsPerUv;
        xyz += (1.0 - edgeWeight) * tableXyz(vec3(d.centre, -(discWi.z + discWr.z)),
                mipFootprint(footprintTexels + disc));
    }
    if (edgeWeight > 0.0) {
        float samplesAcross = ceil(2.0 * d.reachV * texelsPerUv);
        vec3 sum = vec3(0.0);
        float width = 0.0;
#ifdef BRDF_MAP
        // a map pixel under a disc about as wide (BakedDisc.BOX_BELOW): the rows averaged over the pixel's box, on
        // nodes at least 2 and at most DISC_BOX_NODE_TEXELS table samples apart along u and v, read at level 0
        if (mapPixelHalfWidthUv > 0.0 && d.minorAxis / spreadR < DISC_TABLE_BOX_BELOW) {
            float h = mapPixelHalfWidthUv;
            int nodes = clamp(int(ceil(2.0 * h * texelsPerUv / DISC_BOX_NODE_TEXELS)), 2, DISC_BOX_NODES_MAX);
            int rows = clamp(int(samplesAcross), DISC_MIN_ROWS, DISC_ROWS_MAX);
            float spacing = 2.0 * d.reachV / float(rows);
            MipFootprint level0 = MipFootprint(0.0, vec2(0.0));
            for (int k = 0; k < DISC_ROWS_MAX; k++) {
                if (k >= rows) {
                    break;
                }
                sum += discRow(d, -d.reachV + (float(k) + 0.5) * spacing, level0, h, nodes, width);
            }
        } else
#endif
        {
            // a wide disc: rows 2^L samples apart read at level L or coarser, whose linear interpolant the midpoint
            // rule across v sums exactly, so that a disc takes at most about DISC_FINE_ROWS_MAX rows; its own loop
            // passes nodes = 0 as a constant (one loop for both would make the box's branch a runtime one)
            MipFootprint m = mipFootprint(footprintTexels);
            float coarsen = exp2(max(ceil(log2(samplesAcross / float(DISC_FINE_ROWS_MAX))), 0.0));
            int rows = clamp(int(ceil(samplesAcross / coarsen)), DISC_MIN_ROWS, DISC_ROWS_MAX);
            m.lod = max(m.lod, log2(coarsen));
            float spacing = 2.0 * d.reachV / float(rows);
            for (int k = 0; k < DISC_ROWS_MAX; k++) {
                if (k >= rows) {
                    break;
                }
                sum += discRow(d, -d.reachV + (float(k) + 0.5) * spacing, m, 0.0, 0, width);
            }
        }
        // the rows hold the ellipse's area pi a b exactly
        xyz += width > 0.0 ? edgeWeight * sum * (d.area / width) : vec3(0.0);
    }
    return xyz;
}

#endif
