// The lobes method's spectrum (LobeSpectrum): spectralXyz(uvw) over the footprint set by lobes_footprint.glsl, and
// the monochromatic patchPower. Included by lobes.frag (maps and surfaces) and by baked.frag's bake pass.
#ifndef LOBES_SPECTRUM_GLSL
#define LOBES_SPECTRUM_GLSL
#include "lobes_footprint.glsl"
// Outside any #if: the include is expanded once, where it first appears, whatever the conditions around it.
#include "baked_table.glsl"
#ifdef ENVIRONMENT_TABLE
// Lights wider than the lobes method takes (an environment's extended lights: surface_stage.glsl) read the lobes
// method's own table over their footprint instead (baked_table.glsl): the same physics integrated ahead, where the
// lobes to sum would be counted in thousands per fragment.
bool footprintFromTable = false;
MipFootprint tableFootprint;
#endif

// sigma_f in texels per axis (CoherenceWindow.sigmaTexels); sigma_f per um is sigmaTexels / patchExtentUm.
uniform vec2 sigmaTexels;
uniform float lambdaMinNm;
uniform float lambdaMaxNm;
// HatFilteredSpectrum.rgba(): level-major, (X, Y, Z, 0) per nanometre from lambda_min; level 0 = the density f,
// level l = f averaged over a hat of half-width 2^(l-1) nm; lobeTablePositions entries per level.
uniform sampler1D lobeSpectralTable;
uniform int lobeTablePositions;
// LobeQuadrature.
uniform float lobeNodesPerSigma;
uniform float lobeMaxStepNm;
uniform float lobeReachSigmas;

#ifdef RIGOROUS_ORDERS
// The rigorous orders (OrderCorrection): per order of the patch's ridge, its efficiency from Maxwell's equations
// over the scalar model's, over the wavelength and the incident direction; each lobe's weight is multiplied by its
// order's ratio. Texel (x, y, z) of orderRatios: x the wavelength node, y alpha (the incident wave's direction
// cosine across the ridges, -1 + y * orderAngleStep), z = (order + orderMaxOrder) * betas + |beta| node.
uniform sampler3D orderRatios;
uniform vec3 orderNodes;          // wavelengths, alphas, betas
uniform int orderMaxOrder;
uniform int orderRidges;          // ridges across the patch along its axis
uniform int orderAxis;            // 0: the ridges' period along x, 1: along y
uniform float orderFirstNm;
uniform float orderStepNm;
uniform float orderAngleStep;
// omega_i in the patch's frame for the lobes being summed (diffractionXyz sets it)
vec3 orderIncidence = vec3(0.0, 0.0, 1.0);

void setOrderIncidence(vec3 wi) {
    orderIncidence = wi;
}

// OrderCorrection.ratio: trilinear in (lambda, alpha, |beta|) within the order's slab of the texture.
float orderRatio(ivec2 m, float lambdaNm) {
    int along = orderAxis == 0 ? m.x : m.y;
    int order = int(round(-float(along) / float(orderRidges)));
    if (abs(order) > orderMaxOrder) {
        return 1.0;
    }
    float alpha = orderAxis == 0 ? -orderIncidence.x : -orderIncidence.y;
    float beta = abs(orderAxis == 0 ? orderIncidence.y : orderIncidence.x);
    float tj = clamp((lambdaNm - orderFirstNm) / orderStepNm, 0.0, orderNodes.x - 1.0);
    float ta = clamp((alpha + 1.0) / orderAngleStep, 0.0, orderNodes.y - 1.0);
    float tb = clamp(beta / orderAngleStep, 0.0, orderNodes.z - 1.0);
    float slabs = float(2 * orderMaxOrder + 1) * orderNodes.z;
    vec3 stp = vec3((tj + 0.5) / orderNodes.x, (ta + 0.5) / orderNodes.y,
            (float(order + orderMaxOrder) * orderNodes.z + tb + 0.5) / slabs);
    return texture(orderRatios, stp).r;
}
#endif

const int MAX_NODES = 512;   // nodes per lobe below 1 nm spacing (LobeSpectrum.MAX_NODES is a looser guard)
// Whether this fragment's loops ended before their work did. Mesa's llvmpipe ends a shader invocation's loops after
// 65535 iterations of its SIMD group, silently, and a fragment that reaches many lobes then leaves some out: the march
// and the node loops record that they finished, and what did not finish is reported (the BRDF map's alpha).
bool lobesLeftOut = false;
#define SPECTRUM_REPORTS_TRUNCATION 1

// Whether this fragment's spectrum left lobes out because its loops were ended early.
bool spectrumTruncated() {
    return lobesLeftOut;
}
const int MAX_MARCH = 4096;  // texels along the major axis (a guard: 2 x 2048 texels)
const int MAX_LOBES = 1 << 16;        // lobes integrated per fragment (a guard)
const int MAX_MARCH_STEPS = 1 << 20;  // march steps between two batches of lobes (a guard)
// Lobes found before they are integrated: the march runs on until a batch is full, so that a SIMD group's fragments
// march together between batches instead of between single lobes, and integrate a batch each in one loop.
const int LOBE_BATCH = 16;

// The Gaussian window (spectrum_gaussian.glsl's), for diffraction_common's windowed sum, which lobes do not use.
float windowWeight(float offsetTexels, int axis) {
    float q = offsetTexels / sigmaTexels[axis];
    return exp(-0.5 * q * q);
}

float sigmaFPerUm() {
    return sigmaTexels.x / patchExtentUm.x;
}

// LobeWeightTable: per texel (the term grid's), W_m(a) = |T_m(a)|^2 and delta dW/dp at p = -a = k delta, k = 0..K-1
// (layers 0..K-1, (W, delta dW/dp)), interpolated by the cubic Hermite polynomial; layers K..K+3 hold the bounds of
// the interpolant over 8 bins of p in [0, p_max] (bins 2j and 2j + 1 in layer K + j).
uniform sampler2DArray lobeWeights;
uniform int lobeWeightSamples;
uniform float lobePhaseStepPerUm;
uniform float lobeMaxPhasePerUm;
// LobeQuadrature.cutoff: a lobe that can add less than this (white = 1) is skipped before its weight is read.
uniform float lobeCutoff;
#ifdef RIGOROUS_ORDERS
uniform float orderLargestRatio;
#endif

// The cutoff the scalar weights' bounds are compared with: lobeCutoff, over the rigorous orders' largest ratio where
// the lobes take them (a corrected lobe carries up to that ratio times its scalar bound).
float scalarBoundCutoff() {
#ifdef RIGOROUS_ORDERS
    return lobeCutoff / orderLargestRatio;
#else
    return lobeCutoff;
#endif
}

ivec2 weightTexel(ivec2 m) {
    return m + textureSize(lobeWeights, 0).xy / 2;
}

bool weightInBand(ivec2 m) {
    ivec2 texel = weightTexel(m);
    return all(greaterThanEqual(texel, ivec2(0))) && all(lessThan(texel, textureSize(lobeWeights, 0).xy));
}

// W_m(a) (LobeWeightTable.weight): the Hermite cubic between the two samples around p = -a.
float lobeWeight(ivec2 m, float a) {
    float x = clamp(-a / lobePhaseStepPerUm, 0.0, float(lobeWeightSamples - 1));
    int k = min(lobeWeightSamples - 2, int(x));
    float t = x - float(k);
    ivec2 texel = weightTexel(m);
    vec2 lo = texelFetch(lobeWeights, ivec3(texel, k), 0).rg;
    vec2 hi = texelFetch(lobeWeights, ivec3(texel, k + 1), 0).rg;
    float t2 = t * t;
    float t3 = t2 * t;
    return max(0.0, (2.0 * t3 - 3.0 * t2 + 1.0) * lo.x + (t3 - 2.0 * t2 + t) * lo.y + (3.0 * t2 - 2.0 * t3) * hi.x
            + (t3 - t2) * hi.y);
}

int weightBin(float p) {
    return clamp(int(floor(p / lobeMaxPhasePerUm * 8.0)), 0, 7);
}

// LobeWeightTable.bound: the largest weight of texel m for p in [pLo, pHi].
float weightBound(ivec2 m, float pLo, float pHi) {
    ivec2 texel = weightTexel(m);
    int lo = weightBin(pLo);
    int hi = weightBin(pHi);
    float bound = 0.0;
    // bins 2j and 2j + 1 share layer K + j: one fetch per pair
    for (int j = lo / 2; j <= hi / 2; j++) {
        vec2 pair = texelFetch(lobeWeights, ivec3(texel, lobeWeightSamples + j), 0).rg;
        bound = max(bound, max(2 * j >= lo ? pair.x : 0.0, 2 * j + 1 <= hi ? pair.y : 0.0));
    }
    return bound;
}

// LobeWeightTable.blockBound: bins 2j and 2j + 1 of block b's bounds in layer j of lobeBlockBounds.
uniform sampler2DArray lobeBlockBounds;

float blockBound(ivec2 block, float pLo, float pHi) {
    int lo = weightBin(pLo);
    int hi = weightBin(pHi);
    float bound = 0.0;
    for (int j = lo / 2; j <= hi / 2; j++) {
        vec2 pair = texelFetch(lobeBlockBounds, ivec3(block, j), 0).rg;
        bound = max(bound, max(2 * j >= lo ? pair.x : 0.0, 2 * j + 1 <= hi ? pair.y : 0.0));
    }
    return bound;
}

// LobeWeightTable.orderLayer: per block its texels from the largest bound over all bins down, (offset in the block,
// that bound) in slot j at texel (LOBE_BLOCK bc + j % LOBE_BLOCK, LOBE_BLOCK br + j / LOBE_BLOCK) of layer 0; (-1, 0)
// past a block's last texel.
uniform sampler2DArray lobeBlockOrder;

// LobeGeometry.axisBoxInterval: the lambda (nm) at which some centre in [c0, c1] (per um) comes within reach of u on
// one axis; empty when .x > .y.
vec2 axisBoxInterval(float c0, float c1, float u, float reach) {
    float lo = 0.0;
    float hi = 1e30;
    float upper = u + reach;
    if (c0 > 0.0) {
        hi = upper / c0 * 1e3;
    } else if (c0 < 0.0) {
        lo = upper < 0.0 ? upper / c0 * 1e3 : 0.0;
    } else if (upper < 0.0) {
        return vec2(1.0, 0.0);
    }
    float lower = u - reach;
    if (c1 > 0.0) {
        lo = max(lo, lower / c1 * 1e3);
    } else if (c1 < 0.0) {
        if (lower > 0.0) {
            return vec2(1.0, 0.0);
        }
        hi = min(hi, lower / c1 * 1e3);
    } else if (lower > 0.0) {
        return vec2(1.0, 0.0);
    }
    return vec2(lo, hi);
}

// LobeGeometry.boxLambdaIntervalNm: the wavelengths at which some lobe centred in the box [c0, c1] comes within reach
// of uv, clipped to the band and widened by a few float ulps; empty when .x >= .y.
vec2 boxLambdaInterval(vec2 c0, vec2 c1, vec2 uv, vec2 reach) {
    vec2 x = axisBoxInterval(c0.x, c1.x, uv.x, reach.x);
    vec2 y = axisBoxInterval(c0.y, c1.y, uv.y, reach.y);
    if (x.x > x.y || y.x > y.y) {
        return vec2(1.0, 0.0);
    }
    return vec2(max(lambdaMinNm, max(x.x, y.x) * (1.0 - 1e-6)), min(lambdaMaxNm, min(x.y, y.y) * (1.0 + 1e-6)));
}

// HatFilteredSpectrum.rangeMaxRgba: level-major (lobeTablePositions per level), in R the largest spectral weight per
// nanometre of any channel and hat level over positions p .. p + 2^level - 1.
uniform sampler1D lobeDensityMax;

// HatFilteredSpectrum.maxDensity(fromNm, toNm): the largest weight per nanometre of a passage's nodes (the first
// beyond the band one hat further, and the next nanometre below 1 nm), from two overlapping windows.
float passageDensity(float fromNm, float toNm) {
    int a = clamp(int(floor(fromNm - lambdaMinNm)) - 1, 0, lobeTablePositions - 1);
    int b = clamp(int(ceil(toNm - lambdaMinNm)) + WIDEST_HAT_NM + 1, a, lobeTablePositions - 1);
    int level = int(floor(log2(float(b - a + 1)))); // exact below 2^20 (a window one level wider bounds as well)
    return max(texelFetch(lobeDensityMax, level * lobeTablePositions + a, 0).r,
            texelFetch(lobeDensityMax, level * lobeTablePositions + max(0, b - (1 << level) + 1), 0).r);
}
// HatFilteredSpectrum.bandWeight: what a lobe of peak average 1 adds at most over any passage.
uniform float lobeBandWeight;
// The footprint Gaussian's largest eigenvalue (LobeSpectrum.Shape.gaussianMax), set by spectralXyz.
float footprintGaussianMax = 0.0;

// LobeSpectrum.phaseLo and phaseHi: |k w| over a passage [fromNm, toNm]; a disc's directions move w by at most sin R.
vec2 passagePhases(float w, float fromNm, float toNm) {
    float spread = 0.0;
#ifdef LIGHT_DISC
    spread = discOn ? disc.axes.x : 0.0;
#endif
    float k = 6.28318531 * 1e3;
    return vec2(k * max(0.0, abs(w) - spread) / toNm, k * (abs(w) + spread) / fromNm);
}

// LobeSpectrum.lineMass: the line form of a passage's bound, for lobes moving at least at speed (per um) and passing
// the footprint's box at least across away from it; the length form where less (or under a disc, or at rest).
float lineMass(float speed, float across, float fromNm, float toNm, float peak) {
    float widestStep = max(1.0, lobeMaxStepNm);
    float mass = peak * (toNm - fromNm + widestStep);
    bool line = speed > 0.0;
#ifdef LIGHT_DISC
    line = line && !discOn;
#endif
    if (!line) {
        return mass;
    }
    float s = 0.5 * pow(toNm * 1e-3 * sigmaFPerUm(), 2.0) + footprintGaussianMax;
    float e = exp(-across * across / (2.0 * s));
    float step = max(1.0, min(1e3 * sqrt(2.0 * s) / (speed * lobeNodesPerSigma), widestStep));
    return min(mass, 1e3 * sqrt(6.28318531 * s) * e / speed + min(peak, e) * step);
}

// LobeSpectrum.passageMass: a bound on the lobe's footprint average of peak 1 summed over its nodes in [fromNm,
// toNm], the lobe centred at lambda c: the peak held over the passage and one node more, or, without a disc, the
// integral along its line past the footprint plus one node of its largest value.
float passageMass(vec2 c, vec2 uv, float fromNm, float toNm, float peak) {
    float speed = length(c);
    float across = speed > 0.0 ? max(0.0, (abs(uv.x * c.y - uv.y * c.x)
            - footprintHalfWidth.x * abs(c.y) - footprintHalfWidth.y * abs(c.x)) / speed) : 0.0;
    return lineMass(speed, across, fromNm, toNm, peak);
}

// LobeSpectrum.blockPassageMass: passageMass of every lobe centred in the box [c0, c1] (per um) over [fromNm, toNm].
float blockPassageMass(vec2 c0, vec2 c1, vec2 uv, float fromNm, float toNm, float peak) {
    float speed = length(clamp(vec2(0.0), c0, c1));
    vec2 corners[4] = vec2[4](c0, vec2(c1.x, c0.y), c1, vec2(c0.x, c1.y));
    float across = 1e30;
    bool below = false;
    bool above = false;
    for (int corner = 0; corner < 4; corner++) {
        float cross = uv.x * corners[corner].y - uv.y * corners[corner].x;
        below = below || cross <= 0.0;
        above = above || cross >= 0.0;
        across = min(across, abs(cross) / max(length(corners[corner]), 1e-30));
    }
    across = below && above ? 0.0 : max(0.0, across - length(footprintHalfWidth));
    return lineMass(speed, across, fromNm, toNm, peak);
}

// The vector whose component along the major axis is a and along the other b.
vec2 onAxes(int major, float a, float b) {
    return major == 0 ? vec2(a, b) : vec2(b, a);
}

// LobeSpectrum.reaches: whether texel m's lobe over [fromNm, toNm] at w can add at least the cutoff to the pixel at
// uv, given the footprint's peak average of a lobe: its weights' bound times the spectral density's times the bound on
// its footprint average over its nodes, or its peak times the band's weight where less.
bool lobeReaches(ivec2 m, vec2 uv, float w, float fromNm, float toNm, float peak) {
    if (lobeCutoff == 0.0) {
        return true;
    }
    vec2 phases = passagePhases(w, fromNm, toNm);
    float bound = weightBound(m, phases.x, phases.y);
    // the band's weight first: it needs no further fetch
    return bound * peak * lobeBandWeight >= scalarBoundCutoff()
            && bound * passageDensity(fromNm, toNm) * passageMass(vec2(m) / patchExtentUm, uv, fromNm, toNm, peak)
            >= scalarBoundCutoff();
}

// LobeSpectrum.Shape.peak: the largest average over the footprint a lobe of peak 1 can have (sigma_uv the widest).
float axisPeak(float sigmaUv, float h, float variance) {
    float peak = sigmaUv / sqrt(sigmaUv * sigmaUv + 2.0 * variance);
    return h > 0.0 ? min(peak, 1.77245385 * sigmaUv / (2.0 * h)) : peak;
}

float footprintPeak(float widestLobeVariance) {
    float sigma = sqrt(2.0 * widestLobeVariance);
    if (footprintHalfWidth.x > 0.0 || footprintHalfWidth.y > 0.0) {
        return axisPeak(sigma, footprintHalfWidth.x, footprintGaussian.x)
                * axisPeak(sigma, footprintHalfWidth.y, footprintGaussian.z);
    }
    vec3 s = footprintGaussian + vec3(widestLobeVariance, 0.0, widestLobeVariance);
    return sigma * sigma / (2.0 * sqrt(s.x * s.z - s.y * s.y));
}

// The wavelengths (nm) at which a lobe moving as mu = lambda_um c (c per um) comes within reach of uv on both axes,
// clipped to the band (LobeGeometry.lambdaIntervalNm); empty when .x >= .y.
vec2 lambdaInterval(vec2 c, vec2 uv, vec2 reach) {
    vec2 interval = vec2(lambdaMinNm, lambdaMaxNm);
    for (int axis = 0; axis < 2; axis++) {
        if (c[axis] == 0.0) {
            if (abs(uv[axis]) > reach[axis]) {
                return vec2(1.0, 0.0);
            }
        } else {
            float a = (uv[axis] - reach[axis]) / c[axis] * 1e3;
            float b = (uv[axis] + reach[axis]) / c[axis] * 1e3;
            interval = vec2(max(interval.x, min(a, b)), min(interval.y, max(a, b)));
        }
    }
    return interval;
}

// The texel range {lo, hi} of one axis a footprint can reach over wavelengths [shortest, longest] um.
vec2 texelRange(float u, float reach, float extentUm, float shortestUm, float longestUm) {
    float a = (u - reach) * extentUm;
    float b = (u + reach) * extentUm;
    return vec2(min(a / shortestUm, a / longestUm), max(b / shortestUm, b / longestUm));
}

// LobeSpectrum.spacingOnLevels: a target spacing rounded down onto the hat levels (1, 2, 4, 8, 16 nm), or below 1 nm
// a whole part of the band.
float spacingOnLevels(float target) {
    float bandNm = lambdaMaxNm - lambdaMinNm;
    if (target >= 1.0) {
        return exp2(floor(log2(target) + 1e-6));
    }
    return bandNm / ceil(bandNm / max(target, 1e-3) - 1e-4);
}

// LobeSpectrum.spacingNm: the passage's width in nm over the nodes per sigma, on the hat levels or below 1 nm.
float nodeSpacingNm(vec2 c, float fromNm) {
    float lobeVariance = 0.5 * pow(fromNm * 1e-3 * sigmaFPerUm(), 2.0);
    vec2 box = vec2(0.0);
#ifdef LIGHT_DISC
    // under a disc the rims are the passage's edges, as wide as the lobe and the box across them (a disc without
    // rims: as wide as its Gaussian; LobeSpectrum.Shape.passageU)
    box = discOn ? discPassage : vec2(0.0);
#endif
    float width = 1e30;
    if (c.x != 0.0) {
        width = min(width, sqrt(lobeVariance + footprintGaussian.x + box.x) / abs(c.x) * 1e3);
    }
    if (c.y != 0.0) {
        width = min(width, sqrt(lobeVariance + footprintGaussian.z + box.y) / abs(c.y) * 1e3);
    }
    // never wider than the band; below 1 nm a whole number of steps across it (LobeSpectrum.spacingNm)
    float bandNm = lambdaMaxNm - lambdaMinNm;
    return spacingOnLevels(min(min(width / lobeNodesPerSigma, lobeMaxStepNm), bandNm));
}

// LobeSpectrum.lastNode: the last node within the passage, or, for hats ending at the band's end, the first at or
// beyond lambda_max (its hat still covers the band's last part).
int lastNodeIndex(float toNm, float spacing) {
    if (spacing >= 1.0 && toNm >= lambdaMaxNm - 1e-4) {
        return int(ceil((lambdaMaxNm - lambdaMinNm) / spacing - 1e-4));
    }
    return int(floor((toNm - lambdaMinNm) / spacing + 1e-4));
}

// LobeSpectrum.endWeight: below 1 nm the trapezoid's half weights at the band's ends.
float nodeEndWeight(float lambdaNm, float spacing) {
    return spacing < 1.0 && (lambdaNm <= lambdaMinNm + 1e-3 || lambdaNm >= lambdaMaxNm - 1e-3) ? 0.5 : 1.0;
}

// The first table entry of a node spacing's level: HatFilteredSpectrum level 1 + log2(h) for h = 1..16 nm; -1 below
// 1 nm (point weights from level 0, interpolated).
int spectralLevelBase(float spacingNm) {
    return spacingNm >= 1.0 ? (1 + int(floor(log2(spacingNm) + 0.5))) * lobeTablePositions : -1;
}

// HatFilteredSpectrum.weight: h f_h(lambda_j) for node j of a spacing of 1..16 nm (a whole nanometre), h f(lambda_j)
// interpolated in level 0 below 1 nm; entries outside the band are 0. Two fetches either way (no branch).
vec3 spectralWeight(float lambdaNm, float spacingNm, int levelBase) {
    float position = lambdaNm - lambdaMinNm;
    bool hat = levelBase >= 0;
    float p = hat ? floor(position + 0.5) : floor(position);
    float t = hat ? 0.0 : position - p;
    int i = int(p);
    int base = max(levelBase, 0);
    vec3 a = texelFetch(lobeSpectralTable, base + clamp(i, 0, lobeTablePositions - 1), 0).xyz
            * (i >= 0 && i < lobeTablePositions ? 1.0 : 0.0);
    vec3 b = texelFetch(lobeSpectralTable, base + clamp(i + 1, 0, lobeTablePositions - 1), 0).xyz
            * (i + 1 >= 0 && i + 1 < lobeTablePositions ? 1.0 : 0.0);
    return spacingNm * mix(a, b, t);
}

// One lobe's wavelength integral over [fromNm, toNm] (LobeSpectrum.integrate): at every node its weight W_m(k w)
// from the table times its average over the footprint times the spectral weight.
vec3 integrateLobe(ivec2 m, vec2 c, vec3 uvw, float fromNm, float toNm) {
    float spacing = nodeSpacingNm(c, fromNm);
    int j0 = int(ceil((fromNm - lambdaMinNm) / spacing - 1e-4));
    int j1 = lastNodeIndex(toNm, spacing);
    if (spacing < 1.0 && j1 - j0 + 1 > MAX_NODES) {
        spacing = min(1.0, (toNm - fromNm) / float(MAX_NODES - 1));
        j0 = int(ceil((fromNm - lambdaMinNm) / spacing - 1e-4));
        j1 = lastNodeIndex(toNm, spacing);
    }
    int levelBase = spectralLevelBase(spacing);
    float sigmaF = sigmaFPerUm();
    vec3 xyz = vec3(0.0);
    int reached = j0 - 1;
    for (int j = j0; j <= j1; j++) {
        reached = j;
        float lambdaNm = lambdaMinNm + float(j) * spacing;
        float lambdaUm = lambdaNm * 1e-3;
        float w = uvw.z;
        float average;
#ifdef LIGHT_DISC
        if (discOn) {
            vec2 overDisc = discAverage(lambdaUm * sigmaF, lambdaUm * c, uvw);
            average = overDisc.x;
            w = overDisc.y;
        } else {
            average = averagedLobe(lambdaUm * sigmaF, lambdaUm * c, uvw.xy);
        }
#else
        average = averagedLobe(lambdaUm * sigmaF, lambdaUm * c, uvw.xy);
#endif
        float weight = lobeWeight(m, waveNumberPerUm(lambdaNm) * w);
#ifdef RIGOROUS_ORDERS
        weight *= orderRatio(m, lambdaNm);
#endif
        xyz += weight * average * spectralWeight(lambdaNm, spacing, levelBase) * nodeEndWeight(lambdaNm, spacing);
    }
    lobesLeftOut = lobesLeftOut || reached < j1;
    return xyz;
}

#include "lobes_sum.glsl"

// LobeSpectrum.xyz: the lobes whose texels lie near the segment s(lambda), marched along its major axis, integrated
// LOBE_BATCH at a time in the order they are found (the CPU's order: the same sum). The march stops when a batch is
// full: a SIMD group of fragments then integrates as many lobes as its busiest fragment, and culled candidates cost
// only the march.
vec3 spectralXyz(vec3 uvw) {
#ifdef ENVIRONMENT_TABLE
    if (footprintFromTable) {
        return tableXyz(uvw, tableFootprint);
    }
#endif
    bool sums = lobeSums && sumsFit();
#ifdef LIGHT_DISC
    sums = sums && !discOn; // a disc's rims are marched lobe by lobe
#endif
    if (sums) {
        return summedXyz(uvw);
    }
    vec2 uv = uvw.xy;
    float sigmaF = sigmaFPerUm();
    float widest = 0.5 * pow(lambdaMaxNm * 1e-3 * sigmaF, 2.0);
    // the full Gaussian's marginals bound the reach (a box's footprintGaussian is only the light's diagonal part)
    bool box = footprintHalfWidth.x > 0.0 || footprintHalfWidth.y > 0.0;
    vec3 full = footprintGaussian + (box ? lightRankOne : vec3(0.0));
    vec2 reach = footprintHalfWidth + lobeReachSigmas * sqrt(widest + full.xz);
    float peak = footprintPeak(widest);
    footprintGaussianMax = 0.5 * (full.x + full.z) + length(vec2(0.5 * (full.x - full.z), full.y));
#ifdef LIGHT_DISC
    if (discOn) {
        // LobeSpectrum.Shape with a disc: with rims (the disc wider than the narrowest blur) its support, the box,
        // and the lobe's blur; without, its Gaussian's reach; its plateau or small-disc peak times the bound on the
        // gain across the disc
        vec2 boxVariance = footprintHalfWidth * footprintHalfWidth / 3.0;
        float narrowest = min(full.x, full.z) + min(boxVariance.x, boxVariance.y);
        vec3 discGaussian = discCovariance();
        bool rims = disc.axes.y > DISC_GAUSSIAN_BELOW * sqrt(narrowest);
        if (rims) {
            // the box and the disc end where they end (BoxedEdge); the lobe and the Gaussian blur beyond
            reach = footprintHalfWidth + discReach() + lobeReachSigmas * sqrt(widest + full.xz);
            discPassage = boxVariance;
        } else {
            reach = footprintHalfWidth + lobeReachSigmas * sqrt(widest + full.xz + discGaussian.xz);
            discPassage = discGaussian.xz;
        }
        vec3 spread = full + discGaussian;
        vec3 s = spread + vec3(widest, 0.0, widest);
        float sigma = sqrt(2.0 * widest);
        float gaussianPeak = box
                ? axisPeak(sigma, footprintHalfWidth.x, spread.x) * axisPeak(sigma, footprintHalfWidth.y, spread.z)
                : 2.0 * widest / (2.0 * sqrt(s.x * s.z - s.y * s.y));
        float plateau = 3.14159265 * 2.0 * widest * discPeakDensity(-uvw - discWr);
        peak = discGainBound * (rims ? max(plateau, gaussianPeak) : gaussianPeak);
    }
#endif
    float shortest = lambdaMinNm * 1e-3;
    float longest = lambdaMaxNm * 1e-3;
    vec2 xRange = texelRange(uv.x, reach.x, patchExtentUm.x, shortest, longest);
    vec2 yRange = texelRange(uv.y, reach.y, patchExtentUm.y, shortest, longest);
    int major = xRange.y - xRange.x >= yRange.y - yRange.x ? 0 : 1;
    int minor = 1 - major;
    vec2 majorRange = major == 0 ? xRange : yRange;
    ivec2 grid = textureSize(lobeWeights, 0).xy;
    ivec2 gridHalf = grid / 2;
    // LobeSpectrum.marchBlocks: blocks of LOBE_BLOCK texels along the major axis, the blocks across it that the
    // segment reaches there, each block tested against its bound, and the texels of a block that passes either from
    // the largest bound down or row by row within the segment's reach, whichever tests fewer (LobeSpectrum.byRows)
    float passageTexels = 2.0 * reach[minor] * patchExtentUm[minor] / shortest;
    int iFirst = max(int(floor(majorRange.x)), -gridHalf[major]);
    int iLast = min(min(int(ceil(majorRange.y)), iFirst + MAX_MARCH), grid[major] - 1 - gridHalf[major]);
    int biLast = (iLast + gridHalf[major]) / LOBE_BLOCK;
    int bi = iFirst > iLast ? biLast + 1 : (iFirst + gridHalf[major]) / LOBE_BLOCK - 1; // the major block
    int i0 = 0;       // its major texels
    int i1 = -1;
    int kFirst = 0;   // the minor texels its lobes can reach
    int kLast = -1;
    int bk = 0;       // the minor block
    int bkLast = -1;
    int k0 = 0;       // its minor texels
    int k1 = -1;
    bool inBlock = false; // a block that passed its test, whose texels are being tested
    bool rows = false;    // its texels row by row, not from the largest bound down
    int i = 0;            // rows: the major texel in the block
    int m = 0;            // rows: the minor texel, up to mLast
    int mLast = -1;
    ivec2 blockOrigin = ivec2(0); // its first texel in the table
    float blockScale = 0.0; // its bound per unit of a texel's weight bound
    int slot = 0;     // the next of its texels in their order
    vec3 xyz = vec3(0.0);
    bool marched = false; // the march passed its last block
    ivec2 batch[LOBE_BATCH];
    vec2 batchInterval[LOBE_BATCH];
    for (int round = 0; round < MAX_LOBES / LOBE_BATCH; round++) {
        // march until LOBE_BATCH lobes are found or the march ends
        int count = 0;
        bool stalled = true; // the steps ran out before either
        for (int step = 0; step < MAX_MARCH_STEPS; step++) {
            if (inBlock) {
                // the block's next candidates while the batch has room: by rows, or from the largest bound down
                // (LobeWeightTable.orderedTexel) until none left can reach the cutoff; one test for both, so that the
                // fragments of a SIMD group test their candidates together rather than in turn with their blocks'
                for (int n = 0; n < LOBE_BLOCK && inBlock && count < LOBE_BATCH; n++) {
                    ivec2 candidate;
                    bool reachable;
                    if (rows) {
                        if (m > mLast) {
                            // the next major texel of the block: its minor texels within the block and the reach
                            i++;
                            inBlock = i <= i1;
                            vec2 along = lambdaInterval(float(i) / patchExtentUm[major] * vec2(major == 0, major == 1),
                                    uv * vec2(major == 0, major == 1),
                                    mix(vec2(1e30), reach, vec2(major == 0, major == 1)));
                            vec2 minorRange = texelRange(uv[minor], reach[minor], patchExtentUm[minor],
                                    along.x * 1e-3, along.y * 1e-3);
                            bool any = inBlock && along.x < along.y;
                            m = any ? max(k0, int(floor(minorRange.x))) : 0;
                            mLast = any ? min(k1, int(ceil(minorRange.y))) : -1;
                        }
                        candidate = major == 0 ? ivec2(i, m) : ivec2(m, i);
                        reachable = m <= mLast;
                        m = reachable ? m + 1 : m;
                    } else {
                        vec2 entry = texelFetch(lobeBlockOrder, ivec3(blockOrigin + ivec2(slot % LOBE_BLOCK,
                                slot / LOBE_BLOCK), 0), 0).rg;
                        slot++;
                        reachable = entry.x >= 0.0 && entry.y * blockScale >= scalarBoundCutoff();
                        inBlock = reachable && slot < LOBE_BLOCK * LOBE_BLOCK;
                        int offset = int(entry.x);
                        candidate = blockOrigin + ivec2(offset % LOBE_BLOCK, offset / LOBE_BLOCK) - gridHalf;
                    }
                    if (reachable) {
                        vec2 at = lambdaInterval(vec2(candidate) / patchExtentUm, uv, reach);
                        if (at.x < at.y && lobeReaches(candidate, uv, uvw.z, at.x, at.y, peak)) {
                            batch[count] = candidate;
                            batchInterval[count] = at;
                            count++;
                        }
                    }
                }
                if (count == LOBE_BATCH) {
                    stalled = false;
                    break;
                }
            } else if (bk < bkLast) {
                // the next minor block: tested against its bound over the wavelengths its lobes come within reach
                bk++;
                k0 = max(kFirst, bk * LOBE_BLOCK - gridHalf[minor]);
                k1 = min(kLast, bk * LOBE_BLOCK + LOBE_BLOCK - 1 - gridHalf[minor]);
                vec2 lo = onAxes(major, float(i0), float(k0)) / patchExtentUm;
                vec2 hi = onAxes(major, float(i1), float(k1)) / patchExtentUm;
                vec2 at = boxLambdaInterval(lo, hi, uv, reach);
                ivec2 block = major == 0 ? ivec2(bi, bk) : ivec2(bk, bi);
                // at least each texel's lobeReaches: their passages lie within the block's
                vec2 phases = passagePhases(uvw.z, at.x, at.y);
                float bound = at.x < at.y ? blockBound(block, phases.x, phases.y) : 0.0;
                inBlock = at.x < at.y && bound * peak * lobeBandWeight >= scalarBoundCutoff();
                // the band's weight first: it needs no further fetch
                blockScale = inBlock ? min(peak * lobeBandWeight, passageDensity(at.x, at.y)
                        * blockPassageMass(lo, hi, uv, at.x, at.y, peak)) : 0.0;
                inBlock = inBlock && bound * blockScale >= scalarBoundCutoff();
                blockOrigin = block * LOBE_BLOCK;
                slot = 0;
                // LobeSpectrum.byRows: the rows' texels within reach, at most; rows where the bound order would test
                // LOBE_ROWS_FACTOR times as many before the cutoff stops it
                int across = min(k1 - k0 + 1, int(passageTexels) + 2);
                int slots = LOBE_ROWS_FACTOR * (i1 - i0 + 1) * across;
                vec2 last = slots < LOBE_BLOCK * LOBE_BLOCK ? texelFetch(lobeBlockOrder, ivec3(blockOrigin
                        + ivec2(slots % LOBE_BLOCK, slots / LOBE_BLOCK), 0), 0).rg : vec2(-1.0, 0.0);
                rows = inBlock && last.x >= 0.0 && last.y * blockScale >= scalarBoundCutoff();
                i = i0 - 1;
                m = 0; // no row: texel indices run negative, so emptiness is m > mLast, not a sentinel
                mLast = -1;
            } else {
                // the next major block: the minor blocks its lobes can reach
                bi++;
                if (bi > biLast) {
                    marched = true;
                    stalled = false;
                    break;
                }
                i0 = max(iFirst, bi * LOBE_BLOCK - gridHalf[major]);
                i1 = min(iLast, bi * LOBE_BLOCK + LOBE_BLOCK - 1 - gridHalf[major]);
                vec2 along = boxLambdaInterval(onAxes(major, float(i0), 0.0) / patchExtentUm,
                        onAxes(major, float(i1), 0.0) / patchExtentUm, onAxes(major, uv[major], 0.0),
                        onAxes(major, reach[major], 1.0));
                bool any = along.x < along.y;
                vec2 minorRange = texelRange(uv[minor], reach[minor], patchExtentUm[minor], along.x * 1e-3,
                        along.y * 1e-3);
                kFirst = max(int(floor(minorRange.x)), -gridHalf[minor]);
                kLast = min(int(ceil(minorRange.y)), grid[minor] - 1 - gridHalf[minor]);
                any = any && kFirst <= kLast;
                bk = any ? (kFirst + gridHalf[minor]) / LOBE_BLOCK - 1 : 0;
                bkLast = any ? (kLast + gridHalf[minor]) / LOBE_BLOCK : -1;
                inBlock = false;
                rows = false;
                m = 0;
                mLast = -1;
            }
        }
        int integrated = 0;
        for (int b = 0; b < count; b++) {
            xyz += integrateLobe(batch[b], vec2(batch[b]) / patchExtentUm, uvw, batchInterval[b].x,
                    batchInterval[b].y);
            integrated++;
        }
        lobesLeftOut = lobesLeftOut || integrated < count;
        if (marched || stalled) {
            break;
        }
    }
    lobesLeftOut = lobesLeftOut || !marched;
    return xyz;
}

// The monochromatic map: |P(lambda)|^2 at the centre direction, sum_m |T_m|^2 exp(-|uv - lambda m / L|^2 /
// (lambda sigma_f)^2) (LobeSpectrum.power with a point footprint).
float patchPower(vec3 uvw, float lambdaNm) {
    float lambdaUm = lambdaNm * 1e-3;
    float sigmaUv = lambdaUm * sigmaFPerUm();
    vec2 reach = vec2(lobeReachSigmas * sigmaUv * 0.70710678);
    vec2 lo = (uvw.xy - reach) * patchExtentUm / lambdaUm;
    vec2 hi = (uvw.xy + reach) * patchExtentUm / lambdaUm;
    float a = waveNumberPerUm(lambdaNm) * uvw.z;
    float sum = 0.0;
    for (int y = int(floor(lo.y)); y <= int(ceil(hi.y)); y++) {
        for (int x = int(floor(lo.x)); x <= int(ceil(hi.x)); x++) {
            ivec2 m = ivec2(x, y);
            if (!weightInBand(m)) {
                continue;
            }
            vec2 d = (uvw.xy - lambdaUm * vec2(m) / patchExtentUm) / sigmaUv;
#ifdef RIGOROUS_ORDERS
            sum += lobeWeight(m, a) * orderRatio(m, lambdaNm) * exp(-dot(d, d));
#else
            sum += lobeWeight(m, a) * exp(-dot(d, d));
#endif
        }
    }
    return sum;
}

#endif
