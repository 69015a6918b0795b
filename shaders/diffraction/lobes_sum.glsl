// The lobes method's texel sums (LobeSumTable, LobeSpectrum.summedXyz): where lobes are at least as wide as a texel's
// cell (scans wider than about two thirds of the coherence length), the texels under the footprint's box are summed
// from quadrant tables of outward sums, four corners per quadrant the box covers, at wavelength nodes, instead of
// marching over the lobes one by one. Included by lobes_spectrum.glsl after its node and spectral helpers.
#ifndef LOBES_SUM_GLSL
#define LOBES_SUM_GLSL

// Whether this patch's footprints sum texels (LobeSumTable.applies); a disc light marches over its lobes.
uniform bool lobeSums;
// Per interval [k, k + 1] of the weight table's samples of p = -a: the quadrants' outward sums of (W, delta dW/dp) at
// k and at k + 1, RGBA, filtered linearly; quadrant (qx, qy) at (qx, qy) * (lobeSumCells + 2), its corner I at texel
// I, 0 from I = lobeSumCells on.
uniform sampler2DArray lobeSumTable;
uniform vec2 lobeSumCells;
// Texels per cell (LobeSumTable.cellTexels).
uniform float lobeSumCellTexels;
uniform float lobeSumNodesPerBox;

// MAX_SUM_NODES: the most wavelength nodes a footprint takes, a define from LobeSpectrum.MAX_SUM_NODES
// (DiffractionShaders).

// LobeSumTable.axisPieces: the parts of [lo, hi] (texels) in the halves m >= 0 (.xy) and m < 0 (.zw) of an axis, in
// each half's coordinate t = +-(s + 1/2) / c (cells) clamped to [0, cells]; an empty part has inner >= outer.
vec4 sumAxisParts(float lo, float hi, float cells) {
    vec4 parts = vec4(0.0);
    if (hi > -0.5) {
        parts.xy = clamp(vec2(max(lo, -0.5) + 0.5, hi + 0.5) / lobeSumCellTexels, 0.0, cells);
    }
    if (lo < -0.5) {
        parts.zw = clamp(vec2(-(min(hi, -0.5) + 0.5), -(lo + 0.5)) / lobeSumCellTexels, 0.0, cells);
    }
    return parts;
}

// 1 / the table's size in texels (set once per fragment by summedXyz).
vec2 sumTexel;

// The outward sums' four values (at samples k and k + 1) at local corner t of the quadrant at origin, filtered
// bilinearly between the table's corners.
vec4 sumCorner(vec2 origin, vec2 t, float layer) {
    return texture(lobeSumTable, vec3((origin + t + 0.5) * sumTexel, layer));
}

// LobeSumTable.boxSum: the spread weights W'_m(a) integrated over the box [lo, hi] in texels: per quadrant the four
// corners' Hermite data combined, then interpolated once (the cubic is linear in its data).
float lobeBoxSum(vec2 lo, vec2 hi, float a) {
    float x = clamp(-a / lobePhaseStepPerUm, 0.0, float(lobeWeightSamples - 1));
    int k = min(lobeWeightSamples - 2, int(x));
    float h = x - float(k);
    float h2 = h * h;
    float h3 = h2 * h;
    vec4 basis = vec4(2.0 * h3 - 3.0 * h2 + 1.0, h3 - 2.0 * h2 + h, 3.0 * h2 - 2.0 * h3, h3 - h2);
    float layer = float(k);
    vec4 partsX = sumAxisParts(lo.x, hi.x, lobeSumCells.x);
    vec4 partsY = sumAxisParts(lo.y, hi.y, lobeSumCells.y);
    vec4 ends = vec4(0.0);
    for (int qx = 0; qx < 2; qx++) {
        vec2 tx = qx == 0 ? partsX.xy : partsX.zw;
        if (tx.x >= tx.y) {
            continue;
        }
        for (int qy = 0; qy < 2; qy++) {
            vec2 ty = qy == 0 ? partsY.xy : partsY.zw;
            if (ty.x >= ty.y) {
                continue;
            }
            vec2 origin = vec2(float(qx), float(qy)) * (lobeSumCells + 2.0);
            ends += sumCorner(origin, vec2(tx.x, ty.x), layer) - sumCorner(origin, vec2(tx.y, ty.x), layer)
                    - sumCorner(origin, vec2(tx.x, ty.y), layer) + sumCorner(origin, vec2(tx.y, ty.y), layer);
        }
    }
    return dot(ends, basis);
}

// LobeSpectrum.summedHalfWidthU/V: the footprint's box widened by its Gaussian's variance.
vec2 summedHalfWidth() {
    bool box = footprintHalfWidth.x > 0.0 || footprintHalfWidth.y > 0.0;
    vec3 full = footprintGaussian + (box ? lightRankOne : vec3(0.0));
    return sqrt(footprintHalfWidth * footprintHalfWidth + 3.0 * full.xz);
}

// LobeSpectrum.sumsFit: the box spans a texel's cell on both axes at lambda_max.
bool sumsFit() {
    return all(greaterThanEqual(2.0 * summedHalfWidth() * patchExtentUm / (lambdaMaxNm * 1e-3), vec2(1.0)));
}

// LobeSpectrum.summedXyz: at wavelength nodes, pi (lambda sigma_f)^2 / (4 h_u h_v) times the box's sum, the box
// widened by the footprint's Gaussian to the same variance per axis; nodes spaced so that lobeSumNodesPerBox of them
// see each lobe's passage through the box at lambda_min, on the hat levels or below 1 nm.
vec3 summedXyz(vec3 uvw) {
    vec2 halfWidth = summedHalfWidth();
    float shortestUm = lambdaMinNm * 1e-3;
    // LobeSpectrum.nodeTravel per axis: the nm in which the box moves by its width and a lobe's at lambda_min
    vec2 speed = (abs(uvw.xy) + halfWidth) * patchExtentUm / (shortestUm * shortestUm) * 1e-3; // texels per nm
    vec2 width = 2.0 * halfWidth * patchExtentUm / shortestUm + 1.41421356 * sigmaTexels;
    vec2 travel = width / (lobeSumNodesPerBox * speed);
    float bandNm = lambdaMaxNm - lambdaMinNm;
    float target = min(min(min(travel.x, travel.y), lobeMaxStepNm), bandNm);
    float spacing = spacingOnLevels(max(target, bandNm / float(MAX_SUM_NODES)));
    int last = lastNodeIndex(lambdaMaxNm, spacing);
    int levelBase = spectralLevelBase(spacing);
    vec2 edge = lobeSumCells - 0.5;
    sumTexel = 1.0 / vec2(textureSize(lobeSumTable, 0).xy);
    float sigmaF = sigmaFPerUm();
    float scale = 3.14159265 / (4.0 * halfWidth.x * halfWidth.y);
    vec3 xyz = vec3(0.0);
    for (int j = 0; j <= last; j++) {
        float lambdaNm = lambdaMinNm + float(j) * spacing;
        float lambdaUm = lambdaNm * 1e-3;
        vec2 lo = (uvw.xy - halfWidth) * patchExtentUm / lambdaUm;
        vec2 hi = (uvw.xy + halfWidth) * patchExtentUm / lambdaUm;
        if (any(greaterThanEqual(lo, edge)) || any(lessThanEqual(hi, -edge - 1.0))) {
            continue; // beyond the grid's texels
        }
        float sum = lobeBoxSum(lo, hi, waveNumberPerUm(lambdaNm) * uvw.z);
        float sigmaUv = lambdaUm * sigmaF;
        xyz += scale * sigmaUv * sigmaUv * sum * spectralWeight(lambdaNm, spacing, levelBase)
                * nodeEndWeight(lambdaNm, spacing);
    }
    return xyz;
}

#endif
