// sRGB's transfer function (IEC 61966-2-1; diffract.colour.Srgb): linear light to display values and back, for every
// shader that writes display pixels or reads display-encoded textures.
#ifndef ENGINE_SRGB_GLSL
#define ENGINE_SRGB_GLSL

// Srgb.encode for one channel: clip to [0, 1], then 12.92 c below 0.0031308, 1.055 c^(1/2.4) - 0.055 above.
float srgbEncode(float linear) {
    float c = clamp(linear, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

vec3 srgbEncode(vec3 linear) {
    return vec3(srgbEncode(linear.r), srgbEncode(linear.g), srgbEncode(linear.b));
}

// Srgb.decode: pigmentation textures hold display-encoded bytes; blending happens in linear light.
float srgbDecode(float encoded) {
    return encoded <= 12.92 * 0.0031308 ? encoded / 12.92 : pow((encoded + 0.055) / 1.055, 2.4);
}

vec3 srgbDecode(vec3 encoded) {
    return vec3(srgbDecode(encoded.r), srgbDecode(encoded.g), srgbDecode(encoded.b));
}

#endif
