// The Gaussians a pixel's footprint is made of, as covariances (xx, xy, yy) in (u, v): the surface pixel's own
// (Footprint.surfacePixel) and the light's (LightSource.uvCovariance). Included by lobes_footprint.glsl (the lobes
// method) and baked_table.glsl (the table's lookup).
#ifndef FOOTPRINT_COVARIANCE_GLSL
#define FOOTPRINT_COVARIANCE_GLSL

// A surface pixel: (J_x J_x^T + J_y J_y^T) / 12 of its (u, v) derivatives, the box of the pixel as a Gaussian of equal
// variance.
vec3 pixelCovariance(vec2 dUvDx, vec2 dUvDy) {
    return vec3(dUvDx.x * dUvDx.x + dUvDy.x * dUvDy.x, dUvDx.x * dUvDx.y + dUvDy.x * dUvDy.y,
            dUvDx.y * dUvDx.y + dUvDy.y * dUvDy.y) / 12.0;
}

// along r r^T + across e e^T, r = (cos phi, sin phi) the light's azimuth, e = (-sin phi, cos phi); r = x at normal
// incidence, where the light's covariance is isotropic.
vec3 lightCovarianceAxes(vec3 wi, float along, float across) {
    float sinTheta = length(wi.xy);
    vec2 r = sinTheta > 1e-6 ? wi.xy / sinTheta : vec2(1.0, 0.0);
    return along * vec3(r.x * r.x, r.x * r.y, r.y * r.y) + across * vec3(r.y * r.y, -r.x * r.y, r.x * r.x);
}

// LightSource.uvCovariance: sigma_a^2 (cos^2 theta r r^T + e e^T).
vec3 lightCovariance(vec3 wi, float sigmaRad) {
    float variance = sigmaRad * sigmaRad;
    return lightCovarianceAxes(wi, variance * wi.z * wi.z, variance);
}

#endif
