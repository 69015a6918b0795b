// A glossy dielectric's specular reflection, Cook-Torrance with the GGX (Trowbridge-Reitz) distribution and Smith's
// separable masking-shadowing (Walter et al. 2007, eqs. 33 and 34): f = F D G / (4 cos theta_i cos theta_o), F given
// by the caller. Directions in the surface's frame (z the normal), unit, towards the light and the eye. The staged
// surface draws it in place of the diffraction BRDF (define GGX_ALPHA) to measure what the diffraction costs.
#ifndef ENGINE_GGX_GLSL
#define ENGINE_GGX_GLSL

const float GGX_PI = 3.14159265358979;

// D(m) of the half vector m, roughness alpha (Walter et al. eq. 33).
float ggxDistribution(float cosThetaM, float alpha) {
    float c2 = cosThetaM * cosThetaM;
    float a2 = alpha * alpha;
    float d = c2 * (a2 - 1.0) + 1.0;
    return a2 / (GGX_PI * d * d);
}

// G1(v) of one direction with cos theta_v = c (Walter et al. eq. 34, the half vector on the same side).
float ggxMasking(float c, float alpha) {
    float c2 = max(c * c, 1e-8);
    return 2.0 / (1.0 + sqrt(1.0 + alpha * alpha * (1.0 - c2) / c2));
}

// f_r / F: D G / (4 cos theta_i cos theta_o), 0 below either horizon.
float ggxSpecularOverFresnel(vec3 wi, vec3 wo, float alpha) {
    if (wi.z <= 0.0 || wo.z <= 0.0) {
        return 0.0;
    }
    vec3 m = normalize(wi + wo);
    return ggxDistribution(m.z, alpha) * ggxMasking(wi.z, alpha) * ggxMasking(wo.z, alpha) / (4.0 * wi.z * wo.z);
}

#endif
