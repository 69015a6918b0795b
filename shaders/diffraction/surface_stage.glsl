// The staged surface (define STAGE; diffract.render.Stage): the diffraction BRDF of diffraction_main.glsl, unchanged,
// evaluated per fragment in the frame of the scale the fragment shows, for the key light and the environment's
// extended lights, plus the pigment lit by the same lights and the environment's diffuse irradiance, tone mapped.
//   SCALE_FRAMES        sampler2D scaleFrames (diffract.geometry.ScaledSkin.frameMap): per texel the scale normal's
//                       components along the mesh's T and B, and the scale's long axis in (T, B); the patch's frame
//                       (T', B', N') is rebuilt from it, so scales change the geometry and never the BRDF
//   ENVIRONMENT_LIGHTS  K > 0: K extended lights (diffract.lighting.MedianCut) in world space, linear RGB
//                       irradiance in units of the key light, each of angular diameter
//                       environmentLightAngularDiameterDeg: a variant that filters (FILTERED: lobes, the filtered
//                       baked table) widens its orders by that size as by the key light's (a Gaussian of sigma D / 4,
//                       LightSource), the others see a direction
//   ENVIRONMENT_TABLE   the lobes method with extended lights wider than it takes (sigma_a above
//                       TABLE_BEYOND_SIGMA_RAD): those read the lobes method's baked table over their footprint
//                       (baked_table.glsl), the key light and narrower ones sum their lobes
//   SKY_TABLE           the baked variant's environment lights read their own copies of its table, spread in advance
//                       by each light (diffract.render.SkyTable): one bilinear lookup per light
//   IRRADIANCE_SH, SHADOW_MAP (environment.glsl), TONE_MAP_OPERATOR (tone_mapping.glsl)
//   GGX_ALPHA           the scales as a glossy dielectric (engine/ggx.glsl, this roughness, the patch's refractive
//                       index) in place of the diffraction BRDF, everything else as staged: what the diffraction
//                       costs beside a standard material (Stage.withGlossyScales)
// Every light colour tints the D65 result per channel (the diffraction is integrated under D65): exact for
// D65-coloured lights, an approximation for coloured ones.
#ifndef SURFACE_STAGE_GLSL
#define SURFACE_STAGE_GLSL
#include "/lighting/environment.glsl"
#include "/lighting/tone_mapping.glsl"
#ifdef GGX_ALPHA
#include "/engine/ggx.glsl"
#endif

in vec3 surfaceWorldPosition;
in vec3 surfaceWorldNormal;
in vec3 surfaceWorldTangent;
uniform vec3 cameraPosition;     // engine, world
uniform vec3 lightDirection[ENGINE_MAX_LIGHTS];  // engine: [0] towards the key light, world
#ifdef SCALE_FRAMES
uniform sampler2D scaleFrames;
#endif
#if defined(ENVIRONMENT_LIGHTS) && ENVIRONMENT_LIGHTS > 0
uniform vec3 environmentLightDirection[ENVIRONMENT_LIGHTS];
uniform vec3 environmentLightRgb[ENVIRONMENT_LIGHTS];
uniform float environmentLightAngularDiameterDeg[ENVIRONMENT_LIGHTS];
#endif

// sigma_a of the key light: the settings' light size for the lobes method (lobes_footprint.glsl), which the baked
// table of the lobes method holds already; unused by the variants that do not filter, and 0 for a disc, which the
// lobes method averages over as itself (setDisc).
float keyLightSigmaRad() {
#if defined(FILTERED) && !defined(BAKED_FILTERED) && !defined(LIGHT_DISC)
    return lightSigmaRad;
#else
    return 0.0;
#endif
}

struct SurfaceFrame {
    vec3 t;    // the patch's x axis
    vec3 b;
    vec3 n;
    vec3 base;  // the mesh's own normal: light behind it is behind the body
    vec3 baseT; // the mesh's own tangent frame (baseT, cross(base, baseT), base), smooth across the scales
};

SurfaceFrame surfaceFrame() {
    SurfaceFrame f;
    vec3 n0 = safeNormalize(surfaceWorldNormal);
    vec3 t0 = safeNormalize(surfaceWorldTangent - dot(surfaceWorldTangent, n0) * n0);
    vec3 b0 = cross(n0, t0);
    f.base = n0;
    f.baseT = t0;
#ifdef SCALE_FRAMES
    vec4 texel = texture(scaleFrames, surfaceTexcoord);
    vec3 nLocal = vec3(texel.xy, sqrt(max(1.0 - dot(texel.xy, texel.xy), 0.0)));
    f.n = safeNormalize(nLocal.x * t0 + nLocal.y * b0 + nLocal.z * n0);
    vec3 axis = texel.z * t0 + texel.w * b0;
    f.t = safeNormalize(axis - dot(axis, f.n) * f.n);
    f.b = cross(f.n, f.t);
#else
    f.n = n0;
    f.t = t0;
    f.b = b0;
#endif
    return f;
}

// A scale tilted away from the view at a silhouette would show its back (omega_r below its horizon: no reflection
// and no light let out, a black pixel); its normal is turned towards the view until the view is 1 degree above
// its horizon, the axis kept in the new tangent plane.
const float MIN_VIEW_COS = 0.0175;

SurfaceFrame facingView(SurfaceFrame f, vec3 towardsCamera) {
    float c = dot(f.n, towardsCamera);
    if (c >= MIN_VIEW_COS) {
        return f;
    }
    // n' = cos(a) v_perp + sin(a) v in the plane of n and v, with sin(a) = MIN_VIEW_COS
    vec3 across = safeNormalize(f.n - c * towardsCamera);
    f.n = safeNormalize(sqrt(1.0 - MIN_VIEW_COS * MIN_VIEW_COS) * across + MIN_VIEW_COS * towardsCamera);
    f.t = safeNormalize(f.t - dot(f.t, f.n) * f.n);
    f.b = cross(f.n, f.t);
    return f;
}

vec3 toFrame(SurfaceFrame f, vec3 v) {
    return vec3(dot(v, f.t), dot(v, f.b), dot(v, f.n));
}

// One directional light of linear RGB irradiance `rgb`: its structural colour (exposure x the BRDF's XYZ, in linear
// sRGB) and, for the key light (keyLight), the fraction of it that enters the skin and is scattered by the pigment
// (Algorithm 4's (1 - alpha) cos); the environment's lights reach the pigment through its irradiance instead (counted
// once).
// uvDerivatives: the light's (u, v) = -(omega_i + omega_r).xy across the pixel (dFdx in .xy, dFdy in .zw), taken in
// uniform control flow for the footprint of a filtering variant; sigmaRad: the light's sigma_a = D / 4.
void addLight(SurfaceFrame f, vec3 towardsWorld, vec3 rgb, vec3 wr, bool keyLight, vec4 uvDerivatives,
              float sigmaRad, inout vec3 structural, inout vec3 diffuse) {
    vec3 l = safeNormalize(towardsWorld);
    if (dot(l, f.base) <= 0.0) {
        return; // behind the body
    }
    vec3 wi = toFrame(f, l);
#ifdef LIGHT_DISC
    // the key light is the settings' disc; the environment's lights stay Gaussian
    if (keyLight) {
        setDisc(wi, wr);
    } else {
        discOn = false;
    }
#endif
#if defined(ENVIRONMENT_TABLE)
    // a light wider than the lobes method takes reads the table (lobes_spectrum.glsl)
    footprintFromTable = sigmaRad > TABLE_BEYOND_SIGMA_RAD;
    if (footprintFromTable) {
        tableFootprint = tableSurfacePixel(uvDerivatives.xy, uvDerivatives.zw, wi, sigmaRad, pixelFootprintScale);
    } else {
        setSurfacePixelUnder(uvDerivatives.xy, uvDerivatives.zw, wi, sigmaRad);
    }
#elif defined(FILTERED)
    setSurfacePixelUnder(uvDerivatives.xy, uvDerivatives.zw, wi, sigmaRad);
#endif
    float fresnel = surfaceFresnel(wi, wr, refractiveIndex);
#ifdef GGX_ALPHA
    // a white dielectric coat: f_r cos theta_i of the light's irradiance
    structural += rgb * fresnel * ggxSpecularOverFresnel(wi, wr, GGX_ALPHA) * max(wi.z, 0.0);
#else
    structural += rgb * max(linearSrgbFromXyz(exposure * diffractionXyz(wi, wr)), vec3(0.0));
#endif
    if (keyLight) {
        diffuse += rgb * (1.0 - clamp(fresnel, 0.0, 1.0)) * max(wi.z, 0.0);
    }
}

#ifdef SKY_TABLE
// the difference to the horizontal neighbour within a pixel quad, per row (GLSL 4.5's dFdxFine); GL 3.3's dFdx may
// take one row's difference for both rows
#ifdef GL_ARB_derivative_control
#define HORIZONTAL_DIFFERENCE dFdxFine // enabled at the top of baked.frag
#else
#define HORIZONTAL_DIFFERENCE dFdx
#endif
uniform sampler2DArray skyTable;
uniform vec2 skyTableSamples; // (u, v) samples per axis, w samples per light

// XYZ(u, v, w) of environment light k's spread table: bilinear in (u, v), the nearest of its finely spaced w slices;
// light k's slices follow the k before it.
vec3 skyTableXyz(int k, vec3 uvw) {
    vec2 tc = ((uvw.xy + 2.0) * 0.25 * (skyTableSamples.x - 1.0) + 0.5) / skyTableSamples.x;
    float slice = clamp((uvw.z + 2.0) * 0.5 * (skyTableSamples.y - 1.0), 0.0, skyTableSamples.y - 1.0);
    return textureLod(skyTable, vec3(tc, float(k) * skyTableSamples.y + floor(slice + 0.5)), 0.0).rgb;
}

// Environment light k's structural colour from its spread table (the light's width is in the table: no footprint).
void addSkyLight(SurfaceFrame f, int k, vec3 wr, inout vec3 structural) {
    vec3 l = safeNormalize(environmentLightDirection[k]);
    if (dot(l, f.base) <= 0.0) {
        return; // behind the body
    }
    vec3 wi = toFrame(f, l);
    float gain = gainTimesShadowing(wi, wr);
    if (gain > 0.0) {
        structural += environmentLightRgb[k]
                * max(linearSrgbFromXyz(exposure * gain * skyTableXyz(k, uvwOf(wi, wr))), vec3(0.0));
    }
}

// The environment's structural colour by interleaved sampling (A. Keller and W. Heidrich, "Interleaved Sampling",
// EGWR 2001): of each horizontal pair of pixels the left evaluates the even-numbered lights, the right the odd ones,
// and each adds its neighbour's share, read across the pair by the horizontal derivative (v(x + 1) - v(x)). Both
// pixels of a pair so show the whole sky at half the cost, as if evaluated at half the horizontal resolution: the
// lights are tens of degrees wide, their colour changes slowly across the surface. Called in uniform control flow.
vec3 interleavedSky(SurfaceFrame f, vec3 wr) {
    vec3 share = vec3(0.0);
    int parity = int(gl_FragCoord.x) & 1;
    for (int i = 0; i < ENVIRONMENT_LIGHTS / 2; i++) {
        addSkyLight(f, 2 * i + parity, wr, share);
    }
    vec3 across = HORIZONTAL_DIFFERENCE(share);
    vec3 sky = share + (parity == 0 ? share + across : share - across);
#if ENVIRONMENT_LIGHTS % 2 == 1
    addSkyLight(f, ENVIRONMENT_LIGHTS - 1, wr, sky); // an odd light out: every pixel evaluates it
#endif
    return sky;
}
#endif

// The (u, v) of a light across the pixel (see addLight); zero for variants that do not filter. The derivatives are
// taken in the mesh's own smooth frame (perspective and the body's curvature), not in the scale's: a scale's frame
// jumps at its border, and a finite difference across two scales is not the spread of one footprint (it darkened
// whole 2 x 2 quads at grazing view); within a scale the pixel's own frame still places the lobes.
vec4 uvDerivatives(SurfaceFrame f, vec3 towardsWorld, vec3 towardsCamera) {
#ifdef FILTERED
    SurfaceFrame mesh = f;
    mesh.n = f.base;
    mesh.t = f.baseT;
    mesh.b = cross(f.base, f.baseT);
    vec2 uv = -(toFrame(mesh, safeNormalize(towardsWorld)).xy + toFrame(mesh, towardsCamera).xy);
    return vec4(dFdx(uv), dFdy(uv));
#else
    return vec4(0.0);
#endif
}

vec3 stagedSurfaceLinear() {
    vec3 towardsCamera = safeNormalize(cameraPosition - surfaceWorldPosition);
    SurfaceFrame f = facingView(surfaceFrame(), towardsCamera);
    vec3 wr = toFrame(f, towardsCamera);
    vec3 structural = vec3(0.0);
    vec3 diffuse = vec3(0.0);
    float visible = keyLightVisibility(surfaceWorldPosition, f.base, lightDirection[0]);
    vec4 keyDerivatives = uvDerivatives(f, lightDirection[0], towardsCamera);
    if (visible > 0.0) {
        addLight(f, lightDirection[0], vec3(visible), wr, true, keyDerivatives, keyLightSigmaRad(), structural,
                 diffuse);
    }
#if defined(ENVIRONMENT_LIGHTS) && ENVIRONMENT_LIGHTS > 0
#ifdef SKY_TABLE
    structural += interleavedSky(f, wr);
#else
    for (int k = 0; k < ENVIRONMENT_LIGHTS; k++) {
        addLight(f, environmentLightDirection[k], environmentLightRgb[k], wr, false,
                 uvDerivatives(f, environmentLightDirection[k], towardsCamera),
                 radians(environmentLightAngularDiameterDeg[k]) / 4.0, structural, diffuse);
    }
#endif
#endif
#ifdef PIGMENTATION
    vec3 pigment = srgbDecode(texture(pigmentation, surfaceTexcoord).rgb);
    // the environment's light enters the skin as the view's Fresnel transmission lets it out (reciprocity)
    float viewFresnel = schlickFresnel(max(wr.z, 0.0), schlickR0(refractiveIndex));
    diffuse += (1.0 - viewFresnel) * environmentIrradiance(f.n);
    return (1.0 - diffuseWeight) * (structural + diffuse * pigment) + diffuseWeight * pigment;
#else
    return structural;
#endif
}
#endif
