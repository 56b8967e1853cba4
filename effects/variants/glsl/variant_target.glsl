#pragma once
// The intermediate colour targets of the stage workspaces (effects/variants/): Target_Format picks
// their format (format-by) and the encoding their texels are written in, float for the float
// formats, RGBA8x64, RGBE8 and RGB9E5 in rgba8 for the others (docs/encodings.md).
#include "../../glsl/hdr_encoding.glsl"

uniform int Target_Format;  // rgba32f, rgba16f, r11g11b10f, rgba8 alpha x64, RGBE8, RGB9E5

bool targetIsFloat() { return Target_Format <= 2; }
int targetEncoding() { return Target_Format == 3 ? 5 : Target_Format == 4 ? 4 : Target_Format == 5 ? 3 : 0; }

// Only the encodings Target_Format uses are compiled in (see HDR_DECODE in hdr_storage.glsl).
vec4 encodeTarget(vec3 rgb) {
    switch (Target_Format) {
        case 3: return encodeRGBA8x64(rgb);
        case 4: return encodeRGBE8(rgb);
        default: return encodeRGB9E5(rgb);
    }
}
vec3 decodeTarget(vec4 texel) {
    switch (Target_Format) {
        case 3: return decodeRGBA8x64(texel);
        case 4: return decodeRGBE8(texel);
        case 5: return decodeRGB9E5(texel);
        default: return texel.rgb;
    }
}
// Encoding 0 (the float input, float targets) reads the texel as it is.
#define HDR_DECODE(texel, encoding) ((encoding) == 0 ? (texel).rgb : decodeTarget(texel))
#include "../../glsl/hdr_filter.glsl"

// Float targets keep at most their format's largest finite value (rgba16f 65504; r11g11b10f 65024
// in its 11-bit red and green, 64512 in its 10-bit blue): a larger value could be stored as Inf and
// spread through every later pass.
vec4 storeTarget(vec3 rgb) {
    if (!targetIsFloat()) return encodeTarget(rgb);
    vec3 largest = Target_Format == 1 ? vec3(65504.0) : Target_Format == 2 ? vec3(65024.0, 65024.0, 64512.0) : vec3(3.40282347e38);
    return vec4(min(rgb, largest), 1.0);
}

// Tap loops run to unrolledNot(n) == n rather than to the constant n: a compiler cannot unroll
// them then, and each unrolled tap would inline another decodeTarget, which llvmpipe takes about
// half a second per copy to compile. (Target_Format is never negative.)
int unrolledNot(int n) { return Target_Format >= 0 ? n : 0; }

vec3 loadTarget(sampler2D image, ivec2 texel) { return loadHDR(image, texel, targetEncoding()); }
vec3 loadTargetOrBlack(sampler2D image, ivec2 texel) { return loadHDROrBlack(image, texel, targetEncoding()); }

// Bilinear at `position` (texels) from four texels read by `load`, weighted in a loop.
#define BILINEAR_FROM_TEXELS(image, position, load)                                  \
    vec2 p = position - 0.5;                                                         \
    ivec2 i = ivec2(floor(p));                                                       \
    vec2 f = p - vec2(i);                                                            \
    vec3 sum = vec3(0.0);                                                            \
    for (int k = 0; k < unrolledNot(4); ++k) {                                       \
        ivec2 corner = ivec2(k & 1, k >> 1);                                         \
        vec2 w = mix(1.0 - f, f, vec2(corner));                                      \
        sum += w.x * w.y * load(image, i + corner);                                  \
    }                                                                                \
    return sum;

vec3 loadTargetClamped(sampler2D image, ivec2 texel) {
    return loadHDR(image, clamp(texel, ivec2(0), textureSize(image, 0) - 1), targetEncoding());
}
vec3 decodedBilinearOrBlack(sampler2D image, vec2 position) { BILINEAR_FROM_TEXELS(image, position, loadTargetOrBlack) }
vec3 decodedBilinearClamped(sampler2D image, vec2 position) { BILINEAR_FROM_TEXELS(image, position, loadTargetClamped) }

// Bilinear at `position` (texels) with black outside. Float formats filter in hardware: the sampler
// must say wrap="border" border="0 0 0 0". Encoded texels cannot be filtered: decode four, then weight.
vec3 bilinearTargetOrBlack(sampler2D image, vec2 position) {
    if (targetIsFloat()) return texture(image, position / vec2(textureSize(image, 0))).rgb;
    return decodedBilinearOrBlack(image, position);
}

// Bilinear at `position` (texels) with clamp-to-edge addressing (the sampler must say wrap="clamp").
vec3 bilinearTargetClamped(sampler2D image, vec2 position) {
    if (targetIsFloat()) return texture(image, position / vec2(textureSize(image, 0))).rgb;
    return decodedBilinearClamped(image, position);
}

// The factor n between the input and a target at the reduced size D, read from their sizes (never
// from the Downsample variable): the smallest of 2, 4, 8 with ceil(input / n) == reduced on both
// axes, the targets' rounding rule. An image of at most 2 (or 4) texels per axis matches several
// factors, all of which average it into one texel; the smallest is taken. Other sizes (a viewport
// that is not the input's size): the rounded-up ratio of the heights.
int reductionFactor(ivec2 inputSize, ivec2 reducedSize) {
    for (int n = 2; n <= 8; n *= 2)
        if ((inputSize + n - 1) / n == reducedSize) return n;
    return max(1, (inputSize.y + reducedSize.y - 1) / max(reducedSize.y, 1));
}
