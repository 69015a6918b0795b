// NMM spectral integration (WavelengthSampling.nmm; 003 section 1.5.2 with bounds re-derived from eq. 1.8): the
// nodes are the wavelengths at which the lookup s = |u| L_x / lambda (or |v| L_y / lambda) lands exactly on a DFT
// texel m, lambda = |u| L_x / m, merged with the interval ends; the trapezoid rule on these non-uniform nodes
// carries the Jacobian |d lambda / d m|. Fewer than two crossings (near the specular direction) or more than
// NMM_MAX_NODES nodes fall back to the uniform grid.
#ifndef WAVELENGTHS_NMM_GLSL
#define WAVELENGTHS_NMM_GLSL
#include "wavelengths_uniform.glsl"

#ifndef NMM_MAX_NODES
#error "NMM_MAX_NODES must be defined (DiffractionBrdf.NMM_MAX_NODES)"
#endif

uniform float lambdaMinNm;
uniform float lambdaMaxNm;
// Entry i = (f S xbar, f S ybar, f S zbar, S ybar) at spectralTableFirstNm + i nm, 1 nm apart (D65 x CIE 1931 2
// degrees; f the mirror's normalisation factor, MirrorNormalisation: 1 or (lambda_0 / lambda)^2; the normaliser sums
// S ybar without it).
uniform sampler1D spectralTable;
uniform float spectralTableFirstNm;

// Nodes closer than this are one node (WavelengthSampling.nmmNodes merges within 1e-9 nm in double; float32
// resolves about 3e-5 nm at 500 nm, so coincident u- and v-nodes are merged with this wider tolerance).
const float NMM_MERGE_NM = 1e-3;

// The table's entry at any wavelength, linearly interpolated in the 1 nm table, 0 outside it (as SpectralTable.at
// is).
vec4 d65TimesCmf(float lambdaNm) {
    int size = textureSize(spectralTable, 0);
    float t = lambdaNm - spectralTableFirstNm;
    if (!(t >= 0.0) || t > float(size - 1)) {
        return vec4(0.0);
    }
    int i = min(int(t), size - 2);
    float f = t - float(i);
    vec4 a = texelFetch(spectralTable, i, 0);
    vec4 b = texelFetch(spectralTable, i + 1, 0);
    return a + f * (b - a);
}

// One axis' texel crossings lambda = S / m, m = first..last, with S = |u| L in nm (WavelengthSampling.crossings).
struct Crossings {
    float sNm;
    int first;
    int last;
};

Crossings crossingsOf(float sNm) {
    Crossings c;
    c.sNm = sNm;
    c.first = 1;
    c.last = 0;
    if (sNm > 0.0) {
        c.first = max(1, int(ceil(sNm / lambdaMaxNm)));
        c.last = int(floor(sNm / lambdaMinNm));
    }
    return c;
}

int countOf(Crossings c) {
    return max(0, c.last - c.first + 1);
}

// A value above every wavelength: "this axis has no node left".
const float NO_NODE = 1e30;

// The index m <= mStart of the next node of one axis in increasing lambda (decreasing m), skipping nodes on or
// outside the interval ends (appendCrossings keeps only lambda_min < lambda < lambda_max); first - 1 when the
// axis has no node left.
int mOfNextNode(Crossings c, int m) {
    for (int k = m; k >= c.first; k--) {
        float lambda = c.sNm / float(k);
        if (lambda > lambdaMinNm && lambda < lambdaMaxNm) {
            return k;
        }
    }
    return c.first - 1;
}

// Adds one trapezoid node: weight w = (next - previous) / 2 (Trapezoid.weights), numerator sum of w S cmf |P|^2
// and the normaliser sum of w S ybar (SpectralIntegrator.xyzWeights), both per fragment.
void addNode(vec3 uvw, float lambdaNm, float weightNm, inout vec3 numerator, inout float normaliser) {
    vec4 sCmf = d65TimesCmf(lambdaNm);
    numerator += weightNm * patchPower(uvw, lambdaNm) * sCmf.xyz;
    normaliser += weightNm * sCmf.w;
}

// XYZ on the merged node sequence lambda_min, (u- and v-crossings in increasing order), lambda_max, streamed:
// a node's trapezoid weight needs its two neighbours, so node j is added when node j + 1 is known. Returns false
// (and leaves xyz alone) when the CPU would fall back to the uniform grid.
bool nmmSpectralXyz(vec3 uvw, out vec3 xyz) {
    Crossings cx = crossingsOf(abs(uvw.x) * patchExtentUm.x * 1e3);
    Crossings cy = crossingsOf(abs(uvw.y) * patchExtentUm.y * 1e3);
    int crossings = countOf(cx) + countOf(cy);
    xyz = vec3(0.0);
    if (crossings < 2 || crossings + 2 > NMM_MAX_NODES) {
        return false;
    }
    vec3 numerator = vec3(0.0);
    float normaliser = 0.0;
    int mx = cx.last;
    int my = cy.last;
    float previous = lambdaMinNm;
    float current = lambdaMinNm;
    int unique = 1;
    bool endEmitted = false;
    while (!endEmitted) {
        mx = mOfNextNode(cx, mx);
        my = mOfNextNode(cy, my);
        float nextX = mx >= cx.first ? cx.sNm / float(mx) : NO_NODE;
        float nextY = my >= cy.first ? cy.sNm / float(my) : NO_NODE;
        float next = min(min(nextX, nextY), lambdaMaxNm);
        if (next == nextX && next < lambdaMaxNm) {
            mx--;
        } else if (next == nextY && next < lambdaMaxNm) {
            my--;
        } else {
            endEmitted = true;
        }
        if (next - current <= NMM_MERGE_NM) {
            // a coincident node (u L_x = v L_y, or a crossing on the end): one node, as nmmNodes merges them.
            // The end itself is never dropped: replace the current node by it when they coincide.
            if (endEmitted && unique > 1) {
                current = next;
            }
            continue;
        }
        // `current` now has both neighbours: add it with weight (next - previous) / 2
        // (the first node's "previous" is itself, giving (next - first) / 2).
        addNode(uvw, current, 0.5 * (next - previous), numerator, normaliser);
        previous = current;
        current = next;
        unique++;
    }
    if (unique < 3 || !(normaliser > 0.0)) {
        return false; // nmmNodes returns null for fewer than 3 distinct nodes
    }
    addNode(uvw, current, 0.5 * (current - previous), numerator, normaliser);
    xyz = numerator / normaliser;
    return true;
}

#endif
