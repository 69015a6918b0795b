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

// LobeSpectrum.reaches: whether texel m's lobe over [fromNm, toNm] at w can add at least the cutoff, given the
// footprint's peak average of a lobe.
bool lobeReaches(ivec2 m, float w, float fromNm, float toNm, float peak) {
    if (lobeCutoff == 0.0) {
        return true;
    }
    float spread = 0.0;
#ifdef LIGHT_DISC
    spread = discOn ? discAxes.x : 0.0; // a disc's directions move w by at most sin R about its centre's
#endif
    float k = 6.28318531 * 1e3;
    return weightBound(m, k * max(0.0, abs(w) - spread) / toNm, k * (abs(w) + spread) / fromNm) * peak >= lobeCutoff;
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
            vec2 disc = discAverage(lambdaUm * sigmaF, lambdaUm * c, uvw);
            average = disc.x;
            w = disc.y;
        } else {
            average = averagedLobe(lambdaUm * sigmaF, lambdaUm * c, uvw.xy);
        }
#else
        average = averagedLobe(lambdaUm * sigmaF, lambdaUm * c, uvw.xy);
#endif
        float weight = lobeWeight(m, waveNumberPerUm(lambdaNm) * w);
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
#ifdef LIGHT_DISC
    if (discOn) {
        // LobeSpectrum.Shape with a disc: with rims (the disc wider than the narrowest blur) its support, the box,
        // and the lobe's blur; without, its Gaussian's reach; its plateau or small-disc peak times the bound on the
        // gain across the disc
        vec2 boxVariance = footprintHalfWidth * footprintHalfWidth / 3.0;
        float narrowest = min(full.x, full.z) + min(boxVariance.x, boxVariance.y);
        vec3 discGaussian = discCovariance();
        bool rims = discAxes.y > DISC_GAUSSIAN_BELOW * sqrt(narrowest);
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
        float plateau = 3.14159265 * 2.0 * widest * discPeakDensity(discTable ? vec3(0.0, 0.0, 1.0) : -uvw - discWr);
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
    vec2 majorAxis = vec2(major == 0 ? 1.0 : 0.0, major == 1 ? 1.0 : 0.0);
    vec2 reachMajor = mix(vec2(1e30), reach, majorAxis);
    int first = int(floor(majorRange.x));
    int last = min(int(ceil(majorRange.y)), first + MAX_MARCH);
    int i = first - 1; // the march: major index i, minor index k of kLast
    int k = 0;
    int kLast = -1;
    vec3 xyz = vec3(0.0);
    bool marched = false; // the march passed its last major index
    ivec2 batch[LOBE_BATCH];
    vec2 batchInterval[LOBE_BATCH];
    for (int round = 0; round < MAX_LOBES / LOBE_BATCH; round++) {
        // march until LOBE_BATCH lobes are found or the march ends
        int count = 0;
        bool stalled = true; // the steps ran out before either
        for (int step = 0; step < MAX_MARCH_STEPS; step++) {
            if (k > kLast) {
                // the next major index: the minor texels its lobes can reach
                i++;
                if (i > last) {
                    marched = true;
                    stalled = false;
                    break;
                }
                vec2 along = lambdaInterval(majorAxis * float(i) / patchExtentUm, uv * majorAxis, reachMajor);
                vec2 minorRange = texelRange(uv[minor], reach[minor], patchExtentUm[minor], along.x * 1e-3,
                        along.y * 1e-3);
                bool any = along.x < along.y;
                k = any ? int(floor(minorRange.x)) : 0;
                kLast = any ? int(ceil(minorRange.y)) : -1;
            } else {
                ivec2 candidate = major == 0 ? ivec2(i, k) : ivec2(k, i);
                k++;
                vec2 at = lambdaInterval(vec2(candidate) / patchExtentUm, uv, reach);
                if (weightInBand(candidate) && at.x < at.y && lobeReaches(candidate, uvw.z, at.x, at.y, peak)) {
                    batch[count] = candidate;
                    batchInterval[count] = at;
                    count++;
                    if (count == LOBE_BATCH) {
                        stalled = false;
                        break;
                    }
                }
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
            sum += lobeWeight(m, a) * exp(-dot(d, d));
        }
    }
    return sum;
}

#endif
