// |P|^2 of the PQ approach: sinc interpolation between DFT texels times the replication factor of R_x x R_y
// copies of the patch (TaylorSincSpectrum; 003 section 1.5.3; 004 "PQ factors", "Sinc Interpolation").
#ifndef SPECTRUM_SINC_GLSL
#define SPECTRUM_SINC_GLSL
#include "diffraction_common.glsl"

// Replicas per axis (whole numbers >= 1, as floats): TaylorSincSpectrum.replicasForCoherence or --pq-replicas.
uniform vec2 pqReplicas;

// sin(pi x) / (pi x). Below |pi x| = 1e-3 the series 1 - (pi x)^2 / 6 (error < 1e-14) replaces the quotient:
// GLSL leaves the accuracy of sin() open, and a small absolute error of sin(tiny) / tiny would be large.
float sinc(float x) {
    float px = PI * x;
    if (abs(px) < 1e-3) {
        return 1.0 - px * px / 6.0;
    }
    return sin(px) / px;
}

float windowWeight(float offsetTexels, int axis) {
    return sinc(offsetTexels);
}

// sin(R pi s) / (R sin(pi s)) (TaylorSincSpectrum.normalisedDirichlet): the modulus of the geometric series
// sum_{n<R} e^{-i 2 pi s n} (004 eq. pqgeometricseries) divided by R, so a flat mirror stays 1. With s = m + f,
// (-1)^((R-1) m) sin(R pi f) / (R sin(pi f)); where |R pi f| < 1e-3 the 0/0 becomes its series
// 1 - (R^2 - 1)(pi f)^2 / 6 (next term below 1e-13), never divided.
float normalisedDirichlet(float s, float replicas) {
    if (replicas <= 1.0) {
        return 1.0;
    }
    float m = roundEven(s);
    float sign = (int(abs(m)) * (int(replicas) - 1)) % 2 == 0 ? 1.0 : -1.0;
    float pf = PI * (s - m);
    if (abs(replicas * pf) < 1e-3) {
        return sign * (1.0 - (replicas * replicas - 1.0) * pf * pf / 6.0);
    }
    return sign * sin(replicas * pf) / (replicas * sin(pf));
}

// |P|^2 |p1 + i q1|^2 |p2 + i q2|^2 / (R_x R_y)^2: the 2-D factor is the complex product
// (p1 + i q1)(p2 + i q2) = (p1 p2 - q1 q2) + i (p1 q2 + q1 p2), whose modulus is the product of the per-axis
// moduli (the thesis' eq. pqsubst2 writes q = p1 p2 + q1 q2, a slip). Averaged over the replicas' position the
// window's texels add as powers (TaylorSincSpectrum), and the factor multiplies their sum as well.
float patchPower(vec3 uvw, float lambdaNm) {
    float power = windowedTaylorPower(uvw, lambdaNm);
    vec2 s = lookupTexels(uvw.xy, lambdaNm);
    float dx = normalisedDirichlet(s.x, pqReplicas.x);
    float dy = normalisedDirichlet(s.y, pqReplicas.y);
    return power * dx * dx * dy * dy;
}

#endif
