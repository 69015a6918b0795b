// Tone mapping of linear sRGB to displayable [0, 1], the GLSL twin of diffract.colour.ToneMapping (its class
// comment is the specification). TONE_MAP_OPERATOR: 0 clip, 1 Reinhard (SIGGRAPH 2002 eq. 4, on luminance, hue
// kept), 2 ACES (Narkowicz 2015 fit, per channel). With LINEAR_OUTPUT (FrameOutput.LINEAR) only the exposure's
// stops apply: a still kept as floats holds linear light, and whoever shows it tone maps it.
#ifndef TONE_MAPPING_GLSL
#define TONE_MAPPING_GLSL
#ifndef TONE_MAP_OPERATOR
#define TONE_MAP_OPERATOR 0
#endif

uniform float toneExposureScale; // 2^stops
uniform float toneWhiteLuminance; // Reinhard's Y_white

vec3 toneMap(vec3 linear) {
    vec3 c = max(linear * toneExposureScale, vec3(0.0));
#if defined(LINEAR_OUTPUT)
    return c;
#elif TONE_MAP_OPERATOR == 1
    float y = dot(c, vec3(0.2126, 0.7152, 0.0722));
    if (y <= 0.0) {
        return vec3(0.0);
    }
    float yd = y * (1.0 + y / (toneWhiteLuminance * toneWhiteLuminance)) / (1.0 + y);
    c *= yd / y;
    float m = max(c.r, max(c.g, c.b));
    return m > 1.0 ? c / m : c;
#elif TONE_MAP_OPERATOR == 2
    return clamp(c * (2.51 * c + 0.03) / (c * (2.43 * c + 0.59) + 0.14), 0.0, 1.0);
#else
    return min(c, vec3(1.0));
#endif
}
#endif
