// Shared by every diffraction shader (flss.frag, nmm.frag, pq.frag): colour, Fresnel, shadowing, the gain factor,
// the Taylor coefficients, the Taylor-term lookup and texture blending. Everything here mirrors a CPU class of
// diffract.optics / diffract.colour; the CPU code is the specification, the GPU computes the same in float32.
#ifndef DIFFRACTION_COMMON_GLSL
#define DIFFRACTION_COMMON_GLSL

// Compile-time configuration, injected as #defines by diffract.render.DiffractionShaders:
//   TAYLOR_HIGHEST_ORDER  N, the last Taylor order (N + 1 terms; BrdfSettings.highestOrder)
//   WINDOW_RADIUS         R, the window covers (2R + 1)^2 texels (BrdfSettings.windowRadius)
//   WINDOW_RADIUS_X/_Y    per-axis radii (BrdfSettings.windowRadii, e.g. automatic from sigma_f); default R
//   NMM_MAX_NODES         NMM's node budget (DiffractionBrdf.NMM_MAX_NODES)
//   XYZ_TO_LINEAR_SRGB    mat3(...) constructor of Srgb.xyzToLinearMatrix()
//   BRDF_MAP | SURFACE    which vertex shader feeds the fragment shader
//   MONOCHROMATIC         BRDF map of the relative BRDF at lambdaNm instead of XYZ
//   PIGMENTATION          surface path: blend with a pigmentation texture (Algorithm 4)
//   PHASE_CENTRED         expand around the nearest phase centre (taylor_centred.glsl); TAYLOR_HIGHEST_ORDER is
//                         then the last order per centre
//   TERMS_UNORM8          terms stored [0, 1]-normalised as 8-bit bytes (003 eq. 1.1; NormalisedTerms)
//   GAIN_RAYLEIGH_RICE    the factor in front of |P|^2 is Rayleigh-Rice's (GainModel.RAYLEIGH_RICE); without it Stam's
//                         gain factor and shadowing
//   FRESNEL_THESIS        Stam's gain factor squares Schlick's reflectance as eq. cfact prints it (GainModel.THESIS)
//   WINDOW_FIXED          one coherence window at the DFT's origin: texels add as complex amplitudes, squared after
//                         (the thesis); without it the window is averaged over its position and texels add as powers
//                         (WindowPlacement)
//   WINDOW_LOCAL          the window under the surface point this fragment sees, averaged over the pixel's footprint
//                         on the skin: texels add in pairs, each pair damped by the footprint (LocalWindow)
#if defined(TERMS_UNORM8) && defined(PHASE_CENTRED)
#error "8-bit terms hold the thesis' series around 0 only (DiffractionTextures.ofPhaseCentred refuses them)"
#endif
#if defined(WINDOW_FIXED) && defined(WINDOW_LOCAL)
#error "define at most one of WINDOW_FIXED and WINDOW_LOCAL (WindowPlacement)"
#endif
#if !defined(TAYLOR_HIGHEST_ORDER) || !defined(WINDOW_RADIUS) || !defined(XYZ_TO_LINEAR_SRGB)
#error "TAYLOR_HIGHEST_ORDER, WINDOW_RADIUS and XYZ_TO_LINEAR_SRGB must be defined (see DiffractionShaders)"
#endif

#ifndef WINDOW_RADIUS_X
#define WINDOW_RADIUS_X WINDOW_RADIUS
#endif
#ifndef WINDOW_RADIUS_Y
#define WINDOW_RADIUS_Y WINDOW_RADIUS
#endif

const float PI = 3.14159265358979;
const int TERM_COUNT = TAYLOR_HIGHEST_ORDER + 1;

// DFT_n = fftshift(ifft2((i h)^n)) for n = 0..N, layer n, texel (x = col, y = row), RG = (Re, Im) (TaylorTerms).
uniform sampler2DArray taylorTerms;
// L = (cols dH_x, rows dH_y): the patch extent, the DFT's period (PatchSpectrum.extentXUm/extentYUm).
uniform vec2 patchExtentUm;
// Snake skin: 1.5 (GainFactor.SNAKE_SKIN_REFRACTIVE_INDEX).
uniform float refractiveIndex;
// The early stop of the Taylor loop (BrdfSettings.taylorTolerance; 0 = always TAYLOR_HIGHEST_ORDER) and the
// patch's max|h| in um (TaylorTerms.maxAbsHeightUm) for each fragment's x = |k w| max|h|.
uniform float taylorTolerance;
uniform float maxAbsHeightUm;

// ---------------------------------------------------------------------------------------------------------
// Small guards: no fragment may become NaN or Inf.

// normalize() of a zero vector is undefined (0/0); a degenerate direction becomes (0, 0, 0), i.e. "below the
// horizon", which every caller maps to black.
vec3 safeNormalize(vec3 v) {
    float len2 = dot(v, v);
    return len2 > 1e-30 ? v * inversesqrt(len2) : vec3(0.0);
}

// ---------------------------------------------------------------------------------------------------------
// Colour: CIE XYZ (white Y = 1) to display sRGB (Srgb, IEC 61966-2-1).

// Srgb.linearFromXyz: the matrix derived in double from the sRGB primaries, passed in as a #define.
vec3 linearSrgbFromXyz(vec3 xyz) {
    return XYZ_TO_LINEAR_SRGB * xyz;
}

#include "/engine/srgb.glsl"

// What a frame's pixel stores (FrameOutput): display sRGB, clipped; with LINEAR_OUTPUT the linear value itself,
// unclipped, for a still kept as floats.
vec3 frameOutput(vec3 linear) {
#ifdef LINEAR_OUTPUT
    return linear;
#else
    return srgbEncode(linear);
#endif
}

// ---------------------------------------------------------------------------------------------------------
// The wavelength-independent factors of the relative BRDF (GainFactor).

// Schlick's R_0 = ((1 - n) / (1 + n))^2, thesis eq. B.2 (GainFactor.schlickR0).
float schlickR0(float n) {
    float r = (1.0 - n) / (1.0 + n);
    return r * r;
}

// Schlick's R = R_0 + (1 - R_0)(1 - cos beta)^5, eq. B.1 (GainFactor.schlickFresnel).
float schlickFresnel(float cosHalfToView, float r0) {
    float m = 1.0 - clamp(cosHalfToView, 0.0, 1.0);
    float m2 = m * m;
    return r0 + (1.0 - r0) * m2 * m2 * m;
}

// cos of the angle between the half vector and omega_r (GainFactor.cosHalfToView); 0 for omega_i = -omega_r.
float cosHalfToView(vec3 wi, vec3 wr) {
    vec3 h = wi + wr;
    float len = length(h);
    return len > 1e-30 ? dot(wr, h) / len : 0.0;
}

bool aboveHorizon(vec3 wi, vec3 wr) {
    return wi.z > 0.0 && wr.z > 0.0;
}

// Schlick's reflectance of the surface between omega_i and omega_r at refractive index n (1 below the horizon:
// nothing enters the skin there), for the pigment's share of the light (Algorithm 4).
float surfaceFresnel(vec3 wi, vec3 wr, float n) {
    return aboveHorizon(wi, wr) ? schlickFresnel(cosHalfToView(wi, wr), schlickR0(n)) : 1.0;
}

// The Fresnel factor of Stam's C (GainModel.factor): Schlick's power reflectance counted once, F / F(0), or with
// FRESNEL_THESIS eq. cfact as printed, F^2 / F(0)^2.
float fresnelFactor(float f, float r0) {
    float ratio = f / r0;
#ifdef FRESNEL_THESIS
    return ratio * ratio;
#else
    return ratio;
#endif
}

// The gain factor C of 004 eq. cfact: Phi(F) (1 + wi.wr)^2 / (w^2 cos theta_r), w = cos theta_i + cos theta_r
// (GainFactor.gain). Callers check aboveHorizon first, so w^2 cos theta_r > 0: w >= cos theta_r > 0.
float gainFactor(vec3 wi, vec3 wr) {
    float r0 = schlickR0(refractiveIndex);
    float f = schlickFresnel(cosHalfToView(wi, wr), r0);
    float onePlusDot = 1.0 + dot(wi, wr);
    float w = wi.z + wr.z;
    return fresnelFactor(f, r0) * onePlusDot * onePlusDot / (w * w * wr.z);
}

// Stam's V-cavity shadowing and masking, min(1, 2 (n.h)(n.v)/(v.h), 2 (n.h)(n.l)/(v.h)) (GainFactor.shadowing;
// 003 Algorithm 3 line 27). Above the horizon |h| >= h.z > 0 and v.h = cos(half angle) > 0.
float shadowing(vec3 wi, vec3 wr) {
    vec3 h = wi + wr;
    float len = length(h);
    float nDotH = h.z / len;
    float vDotH = max(dot(wr, h) / len, 1e-30);
    float masking = 2.0 * nDotH * wr.z / vDotH;
    float shadow = 2.0 * nDotH * wi.z / vDotH;
    return min(1.0, min(masking, shadow));
}

// Rayleigh-Rice's gain, 4 cos^2 theta_i cos theta_r Q / (R_0 w^2), Q the polarisation factor of a shallow relief
// for unpolarised light (GainFactor.rayleighRice, which derives it). Callers check aboveHorizon first.
float rayleighRiceGain(vec3 wi, vec3 wr) {
    float eps = refractiveIndex * refractiveIndex;
    float ci = wi.z;
    float cr = wr.z;
    float si2 = max(1.0 - ci * ci, 0.0);
    float sr2 = max(1.0 - cr * cr, 0.0);
    float ri = sqrt(eps - si2);
    float rr = sqrt(eps - sr2);
    // s_i s_r cos phi and s_i s_r sin phi, phi = 0 at the specular direction; undefined at the normal, where the
    // sum over polarisations does not depend on it
    float sinProduct = sqrt(si2 * sr2);
    float cosPart = -dot(wi.xy, wr.xy);
    float sinPart = wi.x * wr.y - wi.y * wr.x;
    bool defined = sinProduct >= 1e-6;
    float cosPhi = defined ? cosPart / sinProduct : 1.0;
    float cos2 = defined ? cosPhi * cosPhi : 1.0;
    float sin2 = defined ? (sinPart / sinProduct) * (sinPart / sinProduct) : 0.0;
    float e1 = eps - 1.0;
    float ss = e1 / ((ci + ri) * (cr + rr));
    float sp = e1 * rr / ((ci + ri) * (eps * cr + rr));
    float ps = e1 * ri / ((eps * ci + ri) * (cr + rr));
    float pp = e1 * (ri * rr * cosPhi - eps * sinProduct) / ((eps * ci + ri) * (eps * cr + rr));
    float q = 0.5 * (ss * ss * cos2 + (sp * sp + ps * ps) * sin2 + pp * pp);
    float w = ci + cr;
    return 4.0 * ci * ci * cr * q / (schlickR0(refractiveIndex) * w * w);
}

// The gain model's factor with its shadowing, 0 at or below the horizon (GainFactor.gainTimesShadowing; 003 Alg. 3
// line 27).
float gainTimesShadowing(vec3 wi, vec3 wr) {
    if (!aboveHorizon(wi, wr)) {
        return 0.0;
    }
#ifdef GAIN_RAYLEIGH_RICE
    return rayleighRiceGain(wi, wr);
#else
    return gainFactor(wi, wr) * shadowing(wi, wr);
#endif
}

// (u, v, w) = -omega_i - omega_r (004; 003 Algorithm 3 line 3).
vec3 uvwOf(vec3 wi, vec3 wr) {
    return -wi - wr;
}

// ---------------------------------------------------------------------------------------------------------
// The Taylor series of 004 eq. finalexpression and its texture lookup (003 eq. 1.5-1.10).

// Wavenumber k = 2 pi / lambda in 1/um.
float waveNumberPerUm(float lambdaNm) {
    return 2.0 * PI / (lambdaNm * 1e-3);
}

// 003 eq. 1.8: s = (u L_x / lambda, v L_y / lambda), in texels from the centre texel.
vec2 lookupTexels(vec2 uv, float lambdaNm) {
    return uv * patchExtentUm / (lambdaNm * 1e-3);
}

// (k w)^n / n! by the recurrence c_n = c_{n-1} k w / n, so n! never overflows (TaylorCoefficients.of).
void taylorCoefficients(float kw, out float c[TERM_COUNT]) {
    c[0] = 1.0;
    for (int n = 1; n < TERM_COUNT; n++) {
        c[n] = c[n - 1] * kw / float(n);
    }
}

// taylorExpansion(kw, c): the plain series around 0 or, with PHASE_CENTRED, around the nearest phase centre.
#include "taylor_centred.glsl"

// The order at which this fragment's loop stops (TaylorBound.stopOrder, the same recurrence): the first n whose
// Lagrange bound x^(n+1) e^x / (n+1)! (001 sec. 3.3.3) is at most the tolerance, b_0 = x e^x,
// b_n = b_{n-1} x / (n + 1); TAYLOR_HIGHEST_ORDER for tolerance 0 (the thesis' fixed N).
int taylorStopOrder(float x) {
    if (taylorTolerance == 0.0) {
        return TAYLOR_HIGHEST_ORDER;
    }
    float bound = x * exp(x);
    for (int n = 0; n < TAYLOR_HIGHEST_ORDER; n++) {
        if (bound <= taylorTolerance) {
            return n;
        }
        bound *= x / float(n + 2);
    }
    return TAYLOR_HIGHEST_ORDER;
}

// The centre texel of eq. 1.5, floor(size / 2) per axis (TaylorTerms.centreCol/centreRow).
ivec2 termCentre() {
    return textureSize(taylorTerms, 0).xy / 2;
}

// Whether frequency index m (texels from the centre) lies inside the stored band; outside, the band-limited
// patch has no energy and the texel contributes 0 (TaylorGaussianSpectrum: never clamped to the edge).
bool inBand(ivec2 m) {
    ivec2 texel = m + termCentre();
    ivec2 size = textureSize(taylorTerms, 0).xy;
    return all(greaterThanEqual(texel, ivec2(0))) && all(lessThan(texel, size));
}

// sum_{n <= lastOrder} c_n DFT_n(m) at the exact texel of frequency index m (texelFetch: no filtering), 0 out of
// band; the terms start at layer layerBase (0, or the phase centre's first layer, taylor_centred.glsl).
vec2 taylorSumAt(ivec2 m, float c[TERM_COUNT], int layerBase, int lastOrder) {
    if (!inBand(m)) {
        return vec2(0.0);
    }
    ivec2 texel = m + termCentre();
    vec2 sum = vec2(0.0);
    for (int n = 0; n < TERM_COUNT; n++) {
        if (n > lastOrder) {
            break;
        }
        sum += c[n] * texelFetch(taylorTerms, ivec3(texel, layerBase + n), 0).rg;
    }
    return sum;
}

#ifdef TERMS_UNORM8
// Terms stored [0, 1]-normalised at 8 bits (NormalisedTerms): DFT_n = min_n + v_n range_n per channel, v_n = byte / 255
// as the RG8 texture returns it (003 eq. 1.1 inverted). Per term n: (min Re, min Im, range Re, range Im).
uniform sampler1D termExtrema;

// The de-normalisation folded into the coefficients, once per wavelength instead of once per window texel:
// sum_n c_n DFT_n = sum_n c_n min_n + sum_n (c_n range_n) v_n (per channel; c_n is real).
struct NormalisedWeights {
    vec2 scale[TERM_COUNT];
    vec2 offset;
};

NormalisedWeights normalisedWeights(float c[TERM_COUNT], int lastOrder) {
    NormalisedWeights w;
    w.offset = vec2(0.0);
    for (int n = 0; n < TERM_COUNT; n++) {
        if (n > lastOrder) {
            break; // the fragment's early stop (taylorStopOrder)
        }
        vec4 e = texelFetch(termExtrema, n, 0);
        w.scale[n] = c[n] * e.zw;
        w.offset += c[n] * e.xy;
    }
    return w;
}

// taylorSumAt for normalised terms: the same sum, 0 out of band.
vec2 normalisedTaylorSumAt(ivec2 m, NormalisedWeights w, int lastOrder) {
    if (!inBand(m)) {
        return vec2(0.0);
    }
    ivec2 texel = m + termCentre();
    vec2 sum = w.offset;
    for (int n = 0; n < TERM_COUNT; n++) {
        if (n > lastOrder) {
            break;
        }
        sum += w.scale[n] * texelFetch(taylorTerms, ivec3(texel, n), 0).rg;
    }
    return sum;
}
#endif

#ifdef WINDOW_LOCAL
// The window under this fragment's surface point (LocalWindow): its centre x0 on the scan in um (x along the
// columns, y along the rows) and the covariance (xx, xy, yy) in um^2 of the pixel's footprint there, a Gaussian with
// the covariance of the pixel's box (SkinFootprint.pixelCovarianceUm2). Set by main() before any lookup: from the
// texture coordinates on a surface, from uniforms on a BRDF map.
vec2 localCentreUm = vec2(0.0);
vec3 localFootprintUm2 = vec3(0.0);

// Pairs whose footprint factor is below 1e-7 (float32's resolution of their sum) are left out; where every pair's is,
// the footprint covers the scan and the sum is the averaged window's diagonal: 2 pi^2 k^T Sigma k >= ln(1e7) for all
// k = d / L with integer d != 0 once the smallest eigenvalue of diag(1/L) Sigma diag(1/L) reaches ln(1e7) / (2 pi^2).
const float LOCAL_PAIR_EXPONENT_CUTOFF = 16.118;

// diag(1/L) Sigma diag(1/L): the footprint's covariance in squared periods, (xx, xy, yy).
vec3 localFootprintPeriods2() {
    return localFootprintUm2 / vec3(patchExtentUm.x * patchExtentUm.x, patchExtentUm.x * patchExtentUm.y,
                                    patchExtentUm.y * patchExtentUm.y);
}

// Whether any texel pair keeps a footprint factor of at least 1e-7: else the footprint covers the scan and the
// window's texels add as powers, the averaged window (the same for every wavelength, so decided once per lookup
// before the texels are read).
bool localPairsMatter() {
    vec3 m = localFootprintPeriods2();
    float halfTrace = 0.5 * (m.x + m.z);
    float smallest = halfTrace - sqrt(max(halfTrace * halfTrace - (m.x * m.z - m.y * m.y), 0.0));
    return 2.0 * PI * PI * smallest < LOCAL_PAIR_EXPONENT_CUTOFF;
}

// sum_{k, l} A_k conj(A_l) exp(-2 pi i (o_k - o_l) . x0 / L) exp(-2 pi^2 q(o_k - o_l)) over the window's texels at
// offsets o from its anchor (LocalWindow.power; only offsets enter, so the anchor's index drops out), with
// q(d) = (d / L)^T Sigma (d / L): each amplitude turned by its phase, B_k = A_k exp(-2 pi i o_k . x0 / L), then
// sum_k |B_k|^2 + 2 sum_{k < l} exp(-2 pi^2 q(o_k - o_l)) Re(B_k conj(B_l)).
float localWindowPower(vec2 amplitude[(2 * WINDOW_RADIUS_X + 1) * (2 * WINDOW_RADIUS_Y + 1)]) {
    const int WIDTH = 2 * WINDOW_RADIUS_X + 1;
    const int COUNT = WIDTH * (2 * WINDOW_RADIUS_Y + 1);
    float diagonal = 0.0;
    for (int k = 0; k < COUNT; k++) {
        diagonal += dot(amplitude[k], amplitude[k]);
    }
    vec3 m = localFootprintPeriods2();
    vec2 f = fract(localCentreUm / patchExtentUm);
    for (int k = 0; k < COUNT; k++) {
        vec2 o = vec2(float(k % WIDTH - WINDOW_RADIUS_X), float(k / WIDTH - WINDOW_RADIUS_Y));
        float angle = -2.0 * PI * dot(o, f);
        vec2 a = amplitude[k];
        amplitude[k] = vec2(a.x * cos(angle) - a.y * sin(angle), a.x * sin(angle) + a.y * cos(angle));
    }
    float pairs = 0.0;
    for (int k = 0; k < COUNT; k++) {
        ivec2 ok = ivec2(k % WIDTH, k / WIDTH);
        for (int l = k + 1; l < COUNT; l++) {
            vec2 d = vec2(ok - ivec2(l % WIDTH, l / WIDTH));
            float exponent = 2.0 * PI * PI * (m.x * d.x * d.x + 2.0 * m.y * d.x * d.y + m.z * d.y * d.y);
            if (exponent < LOCAL_PAIR_EXPONENT_CUTOFF) {
                vec2 b = amplitude[k];
                vec2 c = amplitude[l];
                pairs += exp(-exponent) * (b.x * c.x + b.y * c.y);
            }
        }
    }
    return max(diagonal + 2.0 * pairs, 0.0);
}
#endif

// The interpolation kernel of a variant along one axis (0 = x, 1 = y): the Gaussian window (FLSS, NMM) or sinc
// (PQ). Defined by spectrum_gaussian.glsl or spectrum_sinc.glsl.
float windowWeight(float offsetTexels, int axis);

// The window's sum over the (2R_x+1)(2R_y+1) texels around the nearest texel floor(s + 0.5) of T_m = sum_n c_n DFT_n(m)
// weighted by K(s - m) (WindowedTaylorSum.power; 003 Algorithm 3 lines 9-24 with the loops exchanged, which changes
// nothing but the order of the float sums): |sum_m K T_m|^2 with WINDOW_FIXED, the pairs under the footprint with
// WINDOW_LOCAL (localWindowPower), else sum_m K^2 |T_m|^2, the window averaged over its position.
float windowedTaylorPower(vec3 uvw, float lambdaNm) {
    vec2 s = lookupTexels(uvw.xy, lambdaNm);
    float c[TERM_COUNT];
    float kw = waveNumberPerUm(lambdaNm) * uvw.z;
    int layerBase = taylorExpansion(kw, c);
    // the early stop's x is the phase the series actually expands: k w, or k w - a_j around a phase centre
    int lastOrder = taylorStopOrder(abs(expansionPhase(kw)) * maxAbsHeightUm);
    ivec2 anchor = ivec2(floor(s + 0.5));
#ifdef TERMS_UNORM8
    NormalisedWeights normalised = normalisedWeights(c, lastOrder);
#endif
    vec2 p = vec2(0.0);
    float power = 0.0;
#ifdef WINDOW_LOCAL
    bool pairs = localPairsMatter();
    vec2 amplitude[(2 * WINDOW_RADIUS_X + 1) * (2 * WINDOW_RADIUS_Y + 1)];
#endif
    for (int j = -WINDOW_RADIUS_Y; j <= WINDOW_RADIUS_Y; j++) {
        int my = anchor.y + j;
        float weightY = windowWeight(float(my) - s.y, 1);
        for (int i = -WINDOW_RADIUS_X; i <= WINDOW_RADIUS_X; i++) {
            int mx = anchor.x + i;
#ifdef TERMS_UNORM8
            vec2 sum = normalisedTaylorSumAt(ivec2(mx, my), normalised, lastOrder);
#else
            vec2 sum = taylorSumAt(ivec2(mx, my), c, layerBase, lastOrder);
#endif
            float weight = weightY * windowWeight(float(mx) - s.x, 0);
#if defined(WINDOW_FIXED)
            p += weight * sum;
#elif defined(WINDOW_LOCAL)
            if (pairs) {
                amplitude[(j + WINDOW_RADIUS_Y) * (2 * WINDOW_RADIUS_X + 1) + i + WINDOW_RADIUS_X] = weight * sum;
            } else {
                power += weight * weight * dot(sum, sum);
            }
#else
            power += weight * weight * dot(sum, sum);
#endif
        }
    }
#if defined(WINDOW_FIXED)
    return dot(p, p);
#elif defined(WINDOW_LOCAL)
    return pairs ? localWindowPower(amplitude) : power;
#else
    return power;
#endif
}

// ---------------------------------------------------------------------------------------------------------
// Texture blending (003 Algorithm 4, read as physics; the printed algorithm is garbled, see DiffractionShaders):
// of the light reaching the skin a fraction alpha = clamp(F, 0, 1) is reflected at the interface (the structural
// colour, whose gain factor already contains the Fresnel factor) and 1 - alpha enters the skin, where the pigment
// scatters it diffusely (Lambert: times cos theta_i). A constant weight w_d mixes in the pigment as ambient light:
//   c_total = (1 - w_d) (c_diffraction + (1 - alpha) cos(theta_i) c_pigment) + w_d c_pigment,
// all in linear light. w_d = 0 shows pure structural colour; w_d = 1 pure pigment.
vec3 blendPigmentation(vec3 diffractionLinear, vec3 pigmentLinear, float fresnel, float cosThetaI,
                       float diffuseWeight) {
    float alpha = clamp(fresnel, 0.0, 1.0);
    vec3 diffuse = (1.0 - alpha) * max(cosThetaI, 0.0) * pigmentLinear;
    return (1.0 - diffuseWeight) * (diffractionLinear + diffuse) + diffuseWeight * pigmentLinear;
}

#endif
