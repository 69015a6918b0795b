// main() of every variant shader (flss, nmm, pq, lobes, baked). A variant file includes its spectrum
// (spectrum_gaussian.glsl, spectrum_sinc.glsl, lobes_spectrum.glsl or the baked table), defines spectralXyz(uvw) and
// then includes this file.
#ifndef DIFFRACTION_MAIN_GLSL
#define DIFFRACTION_MAIN_GLSL
#include "diffraction_common.glsl"

#if defined(BRDF_MAP) == defined(SURFACE)
#error "define exactly one of BRDF_MAP and SURFACE"
#endif

// sum_j |P(lambda_j)|^2 weights_j over the variant's wavelength nodes (unnormalised by the gain).
vec3 spectralXyz(vec3 uvw);
float patchPower(vec3 uvw, float lambdaNm);

#ifdef FILTERED
// Variants that average over a pixel's footprint and the light (lobes.frag, lobes_footprint.glsl) are told the
// footprint before spectralXyz runs: a BRDF-map pixel's square, or a surface pixel's (u, v) derivatives.
void setMapPixel(float halfWidth);
void setSurfacePixel(vec2 dUvDx, vec2 dUvDy, vec3 wi);
void setSurfacePixelUnder(vec2 dUvDx, vec2 dUvDy, vec3 wi, float sigmaRad); // a light of sigma_a = sigmaRad
#endif

#ifdef LIGHT_DISC
// The lobes method under a disc light places the disc for each pixel (lobes_footprint.glsl).
void setDisc(vec3 wi, vec3 wr);
#endif

// CIE XYZ of the light reflected towards omega_r, D65 white at Y = 1 (DiffractionBrdf.xyz; eq. finalexpression).
vec3 diffractionXyz(vec3 wi, vec3 wr) {
    float gain = gainTimesShadowing(wi, wr);
    if (gain == 0.0) {
        return vec3(0.0);
    }
#if defined(LIGHT_DISC) && !defined(STAGE)
    setDisc(wi, wr);
#endif
#ifdef RIGOROUS_ORDERS
    setOrderIncidence(wi);
#endif
    return gain * spectralXyz(uvwOf(wi, wr));
}

// The relative BRDF at one wavelength (DiffractionBrdf.relative; eq. cpterm).
float relativeBrdf(vec3 wi, vec3 wr, float lambdaNm) {
    float gain = gainTimesShadowing(wi, wr);
    if (gain == 0.0) {
        return 0.0;
    }
#ifdef RIGOROUS_ORDERS
    setOrderIncidence(wi);
#endif
    return gain * patchPower(uvwOf(wi, wr), lambdaNm);
}

out vec4 fragColor;

// A fragment's alpha: 0 where the GL ended the lobes shader's loops before their work was done and lobes were left
// out (lobes_spectrum.glsl), 1 elsewhere; GpuBrdfMap, BakedTable and ShortPixels count the pixels of alpha 0.
float leftOutAlpha() {
#ifdef SPECTRUM_REPORTS_TRUNCATION
    return spectrumTruncated() ? 0.0 : 1.0;
#else
    return 1.0;
#endif
}

#ifdef BRDF_MAP
// ---- BRDF maps (BrdfMap): linear XYZ, or the monochromatic relative BRDF in .r, into an RGBA32F target.
uniform vec3 omegaI;      // towards the light, unit, tangent frame
uniform float mapSizePx;  // S
uniform vec2 mapOriginPx; // lower-left corner of the map in the viewport (0 unless a window centres it)
#ifdef MONOCHROMATIC
uniform float lambdaNm;
#endif
#ifdef DISPLAY_SRGB
uniform float exposure;   // a window shows display sRGB of exposure x XYZ instead of storing linear XYZ
#endif
#ifdef WINDOW_LOCAL
// A map has no surface point: the window's centre on the scan and the footprint's covariance come from the caller
// (GpuBrdfMap.placeWindow; 0 and 0: the fixed window at the scan's origin).
uniform vec2 mapWindowCentreUm;
uniform vec3 mapFootprintUm2;
#endif

void main() {
    // Pixel (i, j), j counted from the top, has its centre at gl_FragCoord = (i + 0.5, S - j - 0.5), so
    // BrdfMap's x = 2 (i + 0.5) / S - 1 and y = 1 - 2 (j + 0.5) / S become 2 gl_FragCoord / S - 1.
    vec2 xy = 2.0 * (gl_FragCoord.xy - mapOriginPx) / mapSizePx - 1.0;
    float zz = 1.0 - xy.x * xy.x - xy.y * xy.y;
    if (!(zz > 0.0)) {
        fragColor = vec4(0.0, 0.0, 0.0, 1.0); // outside the unit disk (x^2 + y^2 >= 1): black, as BrdfMap
        return;
    }
    vec3 wr = vec3(xy, sqrt(zz)); // Direction.fromProjected
#ifdef WINDOW_LOCAL
    localCentreUm = mapWindowCentreUm;
    localFootprintUm2 = mapFootprintUm2;
#endif
#ifdef FILTERED
    setMapPixel(1.0 / mapSizePx); // the pixel's square of side 2 / S (Footprint.mapPixel)
#endif
#ifdef MONOCHROMATIC
    fragColor = vec4(relativeBrdf(omegaI, wr, lambdaNm), 0.0, 0.0, 1.0);
#elif defined(DISPLAY_SRGB)
    vec3 xyz = diffractionXyz(omegaI, wr);
    fragColor = vec4(frameOutput(max(linearSrgbFromXyz(exposure * xyz), vec3(0.0))), leftOutAlpha());
#else
    vec3 xyz = diffractionXyz(omegaI, wr);
    fragColor = vec4(xyz, leftOutAlpha());
#endif
}
#endif

#ifdef SURFACE
// ---- Meshes (003 Algorithm 3 after Algorithm 2): display sRGB.
in vec3 omegaITangent;   // towards the light, tangent frame (surface.vert)
in vec3 toViewerTangent; // towards the eye, tangent frame, unnormalised (interpolates exactly on flat triangles)
in vec2 surfaceTexcoord;
uniform float exposure;  // multiplies linear XYZ before display encoding
#ifdef PIGMENTATION
uniform sampler2D pigmentation;   // display-encoded sRGB bytes
uniform float diffuseWeight;      // w_d of Algorithm 4
#endif

#ifdef STAGE
#include "surface_stage.glsl"
#endif

#ifdef WINDOW_LOCAL
// How the scan lies on the texture coordinates (ScanTiling): um of skin per unit of u and v, and whether the scan's
// columns run along v.
uniform vec2 skinUmPerTexcoord;
uniform bool scanColumnsAlongV;

// The window under this fragment's surface point: x0 = (u, v) scaled to um (ScanTiling.centreUm) and the Gaussian
// with the covariance of the pixel's box mapped onto the skin by the screen-space derivatives J = dx0 / d(x, y),
// (J_x J_x^T + J_y J_y^T) / 12 (SkinFootprint.pixelCovarianceUm2). Called in uniform control flow (derivatives).
void setLocalWindow(vec2 texcoord) {
    vec2 x0 = texcoord * skinUmPerTexcoord;
    if (scanColumnsAlongV) {
        x0 = x0.yx;
    }
    vec2 jx = dFdx(x0);
    vec2 jy = dFdy(x0);
    localCentreUm = x0;
    localFootprintUm2 = vec3(jx.x * jx.x + jy.x * jy.x, jx.x * jx.y + jy.x * jy.y, jx.y * jx.y + jy.y * jy.y) / 12.0;
}
#endif

void main() {
#ifdef WINDOW_LOCAL
    setLocalWindow(surfaceTexcoord);
#endif
#ifdef STAGE
    vec3 staged = toneMap(stagedSurfaceLinear());
    fragColor = vec4(frameOutput(staged), leftOutAlpha());
    return;
#endif
    vec3 wi = safeNormalize(omegaITangent);
    vec3 wr = safeNormalize(toViewerTangent);
#ifdef FILTERED
    // screen-space derivatives in uniform control flow, before anything can return early (Footprint.surfacePixel)
    vec2 uv = uvwOf(wi, wr).xy;
    setSurfacePixel(dFdx(uv), dFdy(uv), wi);
#endif
    vec3 linear = max(linearSrgbFromXyz(exposure * diffractionXyz(wi, wr)), vec3(0.0));
#ifdef PIGMENTATION
    vec3 pigment = srgbDecode(texture(pigmentation, surfaceTexcoord).rgb);
    float fresnel = surfaceFresnel(wi, wr, refractiveIndex);
    linear = blendPigmentation(linear, pigment, fresnel, wi.z, diffuseWeight);
#endif
    fragColor = vec4(frameOutput(linear), leftOutAlpha());
}
#endif

#endif
