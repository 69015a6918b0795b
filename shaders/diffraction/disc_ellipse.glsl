// The cone of a disc light of half-angle R about omega_i, as its directions d place it in (u, v) = -d.xy - omega_r.xy
// (DiscFootprint): an ellipse centred (1 - cos R) omega_i.xy beyond the (u, v) of the light's centre direction, with
// semi-axis a = sin R along e (across the plane of incidence) and b = sin R cos theta_i along r (in it), covering the
// solid angle 2 pi (1 - cos R). Shared by the lobes method (lobes_footprint.glsl) and its baked table
// (baked_disc.glsl).
#ifndef DISC_ELLIPSE_GLSL
#define DISC_ELLIPSE_GLSL

struct DiscEllipse {
    vec2 e;            // the unit axis across the plane of incidence, along which a lies
    vec2 r;            // the unit axis in the plane of incidence, (e.y, -e.x), along which b lies
    vec2 axes;         // (a, b) = (sin R, sin R cos theta_i)
    vec2 centreOffset; // the ellipse's centre less the (u, v) of the light's centre direction
    float solidAngle;  // 2 pi (1 - cos R)
};

DiscEllipse discEllipse(vec3 wi, float halfAngleRad) {
    float cosR = cos(halfAngleRad);
    float sinR = sin(halfAngleRad);
    float sinTheta = length(wi.xy);
    DiscEllipse d;
    d.r = sinTheta < 1e-6 ? vec2(1.0, 0.0) : wi.xy / sinTheta;
    d.e = vec2(-d.r.y, d.r.x);
    d.axes = vec2(sinR, sinR * wi.z);
    d.centreOffset = (1.0 - cosR) * wi.xy;
    d.solidAngle = 6.28318531 * (1.0 - cosR);
    return d;
}

// DiscFootprint.covariance: (xx, xy, yy) of the Gaussian of the disc's covariance, a^2 / 4 along e and b^2 / 4
// along r.
vec3 discEllipseCovariance(DiscEllipse d) {
    float ea = 0.25 * d.axes.x * d.axes.x;
    float rb = 0.25 * d.axes.y * d.axes.y;
    return ea * vec3(d.e.x * d.e.x, d.e.x * d.e.y, d.e.y * d.e.y) + rb * vec3(d.r.x * d.r.x, d.r.x * d.r.y,
            d.r.y * d.r.y);
}

#endif
