// What a pixel of the lobes method averages over (Footprint, LightSource, LobeGeometry on the CPU): a BRDF-map
// pixel's square in (u, v) with the light's Gaussian folded into each axis (define LOBES_BOX), or a surface pixel's
// Gaussian (its screen-space derivatives) plus the light's. Included by lobes.frag. llvmpipe runs a group of
// fragments in SIMD lanes and executes both sides of every branch under a mask, so the box and the Gaussian are
// separate builds and the arithmetic below selects rather than branches.
#ifndef LOBES_FOOTPRINT_GLSL
#define LOBES_FOOTPRINT_GLSL
#include "diffraction_common.glsl"
#include "footprint_covariance.glsl"
#include "disc_ellipse.glsl"

// LIGHT_NODES_MAX: the light arrays' size, a define from LobesGpu.LIGHT_NODES_MAX (DiffractionShaders)

// 1: surface pixels average over their footprint (PixelFilter.BOX); 0: the centre direction only
// (PixelFilter.POINT). A BRDF map's box is the define LOBES_BOX.
uniform float pixelFootprintScale;
// BRDF maps (one omega_i per map): the light's (u, v) covariance split on the CPU (Covariance2.diagonalPlusRankOne)
// into a diagonal part (variances along u and v) and Gauss-Hermite shifts along the rest: (du, dv, weight) per node.
uniform vec2 lightDiagonal;
uniform vec3 lightRankOne; // the rest, (xx, xy, yy): a point pixel takes the light's full covariance
uniform float lightShifts[3 * LIGHT_NODES_MAX];
uniform int lightShiftCount;
// Surfaces: sigma_a = D / 4 of the light in radians (LightSource.sigmaRad); its covariance follows omega_i.
uniform float lightSigmaRad;

// The footprint of the fragment being shaded, set by setMapPixel or setSurfacePixel before spectralXyz runs.
vec2 footprintHalfWidth;   // the box's half-widths in (u, v) (0: none)
vec3 footprintGaussian;    // (xx, xy, yy): the Gaussian convolved with the box (diagonal when there is a box)
int footprintShiftCount;   // Gauss-Hermite shifts of the light's off-axis part (box only; 1 = none)

// A BRDF-map pixel of an S x S map: a square of half-width 1 / S (Footprint.mapPixel) with LOBES_BOX, else its
// centre (PixelFilter.POINT); the light from uniforms.
void setMapPixel(float halfWidth) {
#ifdef LOBES_BOX
    footprintHalfWidth = vec2(halfWidth);
    footprintGaussian = vec3(lightDiagonal.x, 0.0, lightDiagonal.y);
    footprintShiftCount = max(lightShiftCount, 1);
#else
    // no box: the light's full Gaussian is the footprint
    footprintHalfWidth = vec2(0.0);
    footprintGaussian = vec3(lightDiagonal.x, 0.0, lightDiagonal.y) + lightRankOne;
    footprintShiftCount = 1;
#endif
}

// A sample of the baked table (baked_lobes.frag's bake pass): the box of its cell, half-width halfWidth in u and v,
// and the light as an isotropic Gaussian of sigma_a (the table does not know omega_i; a table under a disc is baked
// with a point light, BakedDisc.heldBy, and its lookup integrates the disc).
void setTableCell(float halfWidth) {
    footprintHalfWidth = vec2(halfWidth);
    footprintGaussian = vec3(lightSigmaRad * lightSigmaRad, 0.0, lightSigmaRad * lightSigmaRad);
    footprintShiftCount = 1;
}

// A surface pixel lit by a light of sigma_a = sigmaRad: the Gaussian (J_x J_x^T + J_y J_y^T) / 12 of its (u, v)
// derivatives (Footprint.surfacePixel), plus the light's covariance at omega_i.
void setSurfacePixelUnder(vec2 dUvDx, vec2 dUvDy, vec3 wi, float sigmaRad) {
    vec3 pixel = pixelFootprintScale * pixelCovariance(dUvDx, dUvDy);
    footprintHalfWidth = vec2(0.0);
    footprintGaussian = pixel + lightCovariance(wi, sigmaRad);
    footprintShiftCount = 1;
}

// A surface pixel under the settings' light (lightSigmaRad; a disc is averaged over as itself, setDisc).
void setSurfacePixel(vec2 dUvDx, vec2 dUvDy, vec3 wi) {
#ifdef LIGHT_DISC
    setSurfacePixelUnder(dUvDx, dUvDy, wi, 0.0);
#else
    setSurfacePixelUnder(dUvDx, dUvDy, wi, lightSigmaRad);
#endif
}

// erfc(x) exp(x^2) for x >= 0: the Abramowitz-Stegun 7.1.26 polynomial, which erfcPositive multiplies by exp(-x^2)
// (and normalCdfAndPdf by the exponential it shares with phi).
float erfcOverGaussian(float x) {
    float t = 1.0 / (1.0 + 0.3275911 * x);
    return t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
}

// ErrorFunction.fastErfc for x >= 0: Abramowitz and Stegun 7.1.26, absolute error below 1.5e-7.
float erfcPositive(float x) {
    return erfcOverGaussian(x) * exp(-x * x);
}

// ErrorFunction.fastMassInInterval for an interval, a <= b (its selects assume the order; lobeAxis keeps it):
// (erf(b) - erf(a)) / 2 on the side where it does not cancel, from erfc(|a|) and erfc(|b|) only (two exponentials;
// selects, not branches, so no lane evaluates a third).
float massInInterval(float a, float b) {
    float ea = erfcPositive(abs(a));
    float eb = erfcPositive(abs(b));
    float sameSide = a >= 0.0 ? ea - eb : eb - ea;
    return 0.5 * (a < 0.0 && b > 0.0 ? 2.0 - ea - eb : sameSide);
}

// Phi(z), the standard normal distribution, from the fast erfc on whichever side does not cancel.
float normalCdf(float z) {
    float tail = 0.5 * erfcPositive(abs(z) * 0.70710678);
    return z >= 0.0 ? 1.0 - tail : tail;
}

#ifdef LIGHT_DISC
// (Phi(z), phi(z)) with one exponential: erfcPositive's exp(-x^2) at x = |z| / sqrt 2 is phi's exp(-z^2 / 2).
vec2 normalCdfAndPdf(float z) {
    float e = exp(-0.5 * z * z);
    float tail = 0.5 * erfcOverGaussian(0.70710678 * abs(z)) * e;
    return vec2(z >= 0.0 ? 1.0 - tail : tail, 0.39894228 * e);
}

// BoxedEdge.psi1, psi2: the first and second antiderivatives of Phi.
float normalPsi1(float z) {
    vec2 f = normalCdfAndPdf(z);
    return z * f.x + f.y;
}

float normalPsi2(float z) {
    vec2 f = normalCdfAndPdf(z);
    return 0.5 * ((z * z + 1.0) * f.x + z * f.y);
}

// BoxedEdge.average: Phi((d + n . t) / s) averaged over t in a box whose projection onto n is the sum of two uniforms
// of half-widths ha and hb (a trapezoid), evaluated on the side d <= 0 and mirrored.
float boxedNormalCdf(float d, float ha, float hb, float s) {
    float a = max(ha, hb) / s;
    float b = min(ha, hb) / s;
    float z = -abs(d) / s;
    float lower;
    if (a < 1e-3) {          // BoxedEdge.POINT_BELOW
        lower = normalCdf(z);
    } else if (b < 1e-2 * a) { // BoxedEdge.UNIFORM_BELOW
        lower = max(0.0, (normalPsi1(z + a) - normalPsi1(z - a)) / (2.0 * a));
    } else {
        lower = max(0.0, (normalPsi2(z + a + b) - normalPsi2(z - a + b) - normalPsi2(z + a - b)
                + normalPsi2(z - a - b)) / (4.0 * a * b));
    }
    return d <= 0.0 ? lower : 1.0 - lower;
}
#endif

#ifdef LOBES_BOX
// LobeGeometry.axis with a box: sqrt(pi) sigmaUv times the average over [u - h, u + h] of N(mu, variance).
float lobeAxis(float sigmaUv, float variance, float mu, float u, float h) {
    float scale = 1.0 / (1.41421356 * sqrt(variance));
    // the fast erf's absolute error (1.5e-7) could make a far tail's mass slightly negative
    float mass = max(0.0, massInInterval((u - h - mu) * scale, (u + h - mu) * scale));
    return 1.77245385 * sigmaUv * mass / (2.0 * h);
}
#endif

#ifdef LIGHT_DISC
// A disc light of half-angle lightHalfAngleRad (DiscFootprint): its directions seen from the pixel form an ellipse in
// (u, v) around the pixel's (u, v) at the light's centre plus (1 - cos R) omega_i.xy, semi-axes sin R along
// e = (-sin phi_i, cos phi_i) and sin R cos theta_i along r, of density 1 / (Omega d_z) per unit (u, v). setDisc places
// it for one pixel (diffractionXyz); discOn is false for lights other than the disc (a stage's environment lights).
uniform float lightHalfAngleRad;
// DISC_GAUSSIAN_BELOW, DISC_EDGE_ABOVE and DISC_RING_SAMPLES: DiscFootprint's, defined by DiffractionShaders
bool discOn = false;
DiscEllipse disc; // the disc's ellipse about the pixel's (u, v) at the light's centre
vec3 discWr;
float discCentreGain;
float discGainBound; // DiscFootprint.gainBound: a bound on the gain relative to the centre's across the disc
vec2 discPassage; // variances (u, v) that widen a lobe's passage for the node spacing (LobeSpectrum.Shape.passageU)

// DiscFootprint.gainRatio: C S at the direction (d, d_z), d_z^2 = dz2, relative to the centre's; 0 below the horizon
// or where the centre's gain is 0.
float discGainRatio(vec2 d, float dz2) {
    return dz2 > 0.0 && discCentreGain > 0.0
            ? gainTimesShadowing(vec3(d, sqrt(max(1e-12, dz2))), discWr) / discCentreGain : 0.0;
}

// DiscFootprint.gainBound: the largest gain ratio at the centre (1) and at DISC_RING_SAMPLES directions on the rim
// and on the ring at half its radius, plus half the range of those samples; 1 where the centre's gain is 0.
float discGainBoundAt(vec3 wi, vec3 wr) {
    if (discCentreGain <= 0.0) {
        return 1.0;
    }
    vec2 r = disc.r;
    vec2 centre = -wi.xy - wr.xy + disc.centreOffset;
    float largest = 1.0;
    float smallest = 1.0;
    for (int ring = 1; ring <= 2; ring++) {
        float scale = 1.0 / float(ring);
        for (int k = 0; k < DISC_RING_SAMPLES; k++) {
            float beta = 6.28318531 * (float(k) + 0.5 * float(ring - 1)) / float(DISC_RING_SAMPLES);
            vec2 d = -(centre + scale * (disc.axes.x * cos(beta) * disc.e + disc.axes.y * sin(beta) * r)) - wr.xy;
            float ratio = discGainRatio(d, 1.0 - dot(d, d));
            largest = max(largest, ratio);
            smallest = min(smallest, ratio);
        }
    }
    return largest + 0.5 * (largest - smallest);
}

// The disc's ellipse, density and centre's gain for the pixel at omega_r under the disc about omega_i.
void placeDisc(vec3 wi, vec3 wr) {
    disc = discEllipse(wi, lightHalfAngleRad);
    discWr = wr;
    discCentreGain = gainTimesShadowing(wi, wr);
    discOn = lightHalfAngleRad > 0.0;
}

// DiscFootprint's constructor for the pixel at omega_r under the disc about omega_i, with its gain bound.
void setDisc(vec3 wi, vec3 wr) {
    placeDisc(wi, wr);
    discGainBound = discGainBoundAt(wi, wr);
}

// DiscFootprint.reach: the ellipse's support along u and v plus its centre's offset.
vec2 discReach() {
    vec2 r = disc.r;
    return abs(disc.centreOffset) + sqrt(disc.axes.x * disc.axes.x * disc.e * disc.e
            + disc.axes.y * disc.axes.y * r * r);
}

// DiscFootprint.covariance: (xx, xy, yy) of a^2 / 4 along e and b^2 / 4 along r.
vec3 discCovariance() {
    return discEllipseCovariance(disc);
}

// DiscFootprint.peakDensity: 1 / (Omega d_z) at the disc's lowest direction (theta_i + R).
float discPeakDensity(vec3 wi) {
    float lowest = cos(min(1.5698, acos(min(1.0, wi.z)) + lightHalfAngleRad));
    return 1.0 / (disc.solidAngle * lowest);
}

// DiscFootprint.average: the lobe of spread sigmaUv at mu averaged over the disc from the pixel at uvw (its (u, v, w)
// at the light's centre), with the footprint's box and Gaussian: (the average relative to the centre's gain, w at the
// direction that puts the lobe on the pixel's centre).
vec2 discAverage(float sigmaUv, vec2 mu, vec3 uvw) {
    vec2 uv = uvw.xy;
    float lobeVariance = 0.5 * sigmaUv * sigmaUv;
    vec2 centre = uv + disc.centreOffset;
    vec2 q = mu - centre;
    vec2 r = disc.r;
    float xe = dot(q, disc.e);
    float xr = dot(q, r);
    float a = disc.axes.x;
    float b = disc.axes.y;
    float rho = sqrt((xe / a) * (xe / a) + (xr / b) * (xr / b));
    float ge = xe / (a * a);
    float gr = xr / (b * b);
    float gNorm = length(vec2(ge, gr));
    bool centred = rho < 1e-6 || gNorm < 1e-30;
    vec2 n = centred ? r : (ge * disc.e + gr * r) / gNorm;
    float dist = centred ? b : (1.0 - rho) * rho / gNorm;
    vec3 g = footprintGaussian;
    float gaussianVariance = lobeVariance + g.x * n.x * n.x + 2.0 * g.y * n.x * n.y + g.z * n.y * n.y;
    float blurVariance = gaussianVariance + (footprintHalfWidth.x * footprintHalfWidth.x * n.x * n.x
            + footprintHalfWidth.y * footprintHalfWidth.y * n.y * n.y) / 3.0;
    float s = sqrt(blurVariance);
    float edgeWeight = smoothstep(DISC_GAUSSIAN_BELOW, DISC_EDGE_ABOVE, b / s);
    // the curved rim moved in by s^2 kappa / 2 (DiscFootprint.average)
    float cosT = centred ? 0.0 : xe / (a * rho);
    float sinT = centred ? 1.0 : xr / (b * rho);
    float kappa = a * b / pow(a * a * sinT * sinT + b * b * cosT * cosT, 1.5);
    dist -= 0.5 * blurVariance * kappa;
    // the direction that puts the lobe on the pixel's centre, brought onto the rim from outside
    vec2 onDisc = min(1.0, 1.0 / max(rho, 1e-30)) * q;
    vec2 d = -(centre + onDisc) - discWr.xy;
    float dz2 = 1.0 - dot(d, d);
    float dz = sqrt(max(1e-12, dz2));
    float gain = discGainRatio(d, dz2);
    // the rim blurred by the lobe and the footprint's Gaussian, seen through the box exactly (BoxedEdge)
    float edge = 3.14159265 * sigmaUv * sigmaUv / (disc.solidAngle * dz) * boxedNormalCdf(dist,
            footprintHalfWidth.x * abs(n.x), footprintHalfWidth.y * abs(n.y), sqrt(gaussianVariance));
    // the small disc's Gaussian (LobeGeometry.averagedLobe): a map pixel's box exactly with the Gaussian's diagonal,
    // a surface pixel's Gaussian in full
    vec3 spread = g + discCovariance();
#ifdef LOBES_BOX
    float gaussian = lobeAxis(sigmaUv, lobeVariance + spread.x, mu.x, centre.x, footprintHalfWidth.x)
            * lobeAxis(sigmaUv, lobeVariance + spread.z, mu.y, centre.y, footprintHalfWidth.y);
#else
    vec3 full = spread + vec3(lobeVariance, 0.0, lobeVariance);
    float det = full.x * full.z - full.y * full.y;
    vec2 dc = centre - mu;
    float quad = (full.z * dc.x * dc.x - 2.0 * full.y * dc.x * dc.y + full.x * dc.y * dc.y) / det;
    float gaussian = sigmaUv * sigmaUv / (2.0 * sqrt(det)) * exp(-0.5 * quad);
#endif
    return vec2(gain * mix(gaussian, edge, edgeWeight), -(dz + discWr.z));
}
#endif

// LobeGeometry.averagedLobe: the lobe of spread sigmaUv at mu, averaged over the fragment's footprint at uv (peak 1
// for a point on the lobe's centre). LOBES_BOX (a BRDF map's pixel square, a baked table's cell) or a Gaussian.
float averagedLobe(float sigmaUv, vec2 mu, vec2 uv) {
    float lobeVariance = 0.5 * sigmaUv * sigmaUv;
#ifdef LOBES_BOX
    float sum = 0.0;
    for (int k = 0; k < LIGHT_NODES_MAX; k++) {
        if (k >= footprintShiftCount) {
            break;
        }
        vec3 shift = lightShiftCount > 0 ? vec3(lightShifts[3 * k], lightShifts[3 * k + 1], lightShifts[3 * k + 2])
                : vec3(0.0, 0.0, 1.0);
        vec2 at = uv + shift.xy;
        sum += shift.z * lobeAxis(sigmaUv, lobeVariance + footprintGaussian.x, mu.x, at.x, footprintHalfWidth.x)
                * lobeAxis(sigmaUv, lobeVariance + footprintGaussian.z, mu.y, at.y, footprintHalfWidth.y);
    }
    return sum;
#else
    vec3 s = footprintGaussian + vec3(lobeVariance, 0.0, lobeVariance);
    float det = s.x * s.z - s.y * s.y;
    vec2 d = uv - mu;
    float q = (s.z * d.x * d.x - 2.0 * s.y * d.x * d.y + s.x * d.y * d.y) / det;
    return sigmaUv * sigmaUv / (2.0 * sqrt(det)) * exp(-0.5 * q);
#endif
}

#endif
