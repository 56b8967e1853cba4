#pragma once
// The stage workspaces' intermediate colour targets: Target_Format picks both the target's format
// (format="rgba32f rgba16f r11g11b10f rgba8 rgba8 rgba8" format-by="Target_Format") and how
// texels are written and read (hdr_encoding.glsl: float, float, float, RGBA8x64, RGBE8, RGB9E5).
#include "../../glsl/hdr_encoding.glsl"

uniform int Target_Format;

int targetEncoding() {
    const int encodings[6] = int[6](0, 0, 0, 5, 4, 3);
    return encodings[clamp(Target_Format, 0, 5)];
}

// The largest finite value of each channel of the float formats: a larger one would be stored as
// +Inf. r11g11b10f: exponent at most 15, 6-bit mantissas for red and green, 5-bit for blue.
vec3 targetFloatMax() {
    if (Target_Format == 1) return vec3(65504.0);                    // rgba16f
    if (Target_Format == 2) return vec3(65024.0, 65024.0, 64512.0);  // r11g11b10f
    return vec3(3.40282347e38);                                      // rgba32f
}

vec4 storeTarget(vec3 rgb) {
    int encoding = targetEncoding();
    if (encoding == 0) return vec4(min(hdrSanitize(rgb, 3.40282347e38), targetFloatMax()), 1.0);
    return encodeHDR(rgb, encoding);
}

vec3 loadTarget(sampler2D image, ivec2 texel) { return decodeHDR(texelFetch(image, texel, 0), targetEncoding()); }
