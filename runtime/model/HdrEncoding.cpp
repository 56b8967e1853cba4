#include "model/HdrEncoding.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

// Each function mirrors its GLSL twin operation by operation (the same roundings in the same
// order; CMake builds this file with -ffp-contract=off, as the shader marks its maths `precise`),
// so the codes agree bit for bit.

namespace rmfx {
namespace {

constexpr float inv255 = 1.0f / 255.0f;

// NaN and negatives to 0, then at most `limit` (GLSL's clamp leaves NaN undefined, so both test it).
glm::vec3 sanitized(glm::vec3 c, float limit) {
    for (int k = 0; k < 3; ++k) c[k] = std::isnan(c[k]) ? 0.0f : std::clamp(c[k], 0.0f, limit);
    return c;
}

float peakOf(glm::vec3 c) { return std::max({c.r, c.g, c.b}); }

// Round half up: GLSL's round() leaves the direction of halves to the implementation.
float roundHalfUp(float x) { return std::floor(x + 0.5f); }

glm::uvec4 bytesOf(std::uint32_t word) { return {word & 255u, (word >> 8) & 255u, (word >> 16) & 255u, word >> 24}; }
std::uint32_t wordOf(glm::uvec4 bytes) { return bytes.x | (bytes.y << 8) | (bytes.z << 16) | (bytes.w << 24); }

glm::uvec4 encodeRgb16(glm::vec3 rgb) {
    glm::vec3 c = sanitized(rgb, hdrRgb16Max);
    glm::uvec4 codes(65535u);
    for (int k = 0; k < 3; ++k) codes[k] = static_cast<std::uint32_t>(roundHalfUp(c[k] * 655.35f));
    return codes;
}

glm::vec3 decodeRgb16(glm::uvec4 codes) { return glm::vec3(codes) * (100.0f / 65535.0f); }

// 32-bit codes need more than a float's 24 bits: the shader computes them in double too. Three
// 32-bit codes travel as four 24-bit integers, which rgba32f holds exactly.
glm::uvec4 encodeRgb32(glm::vec3 rgb) {
    glm::vec3 c = sanitized(rgb, hdrRgb32Max);
    std::uint32_t q[3];
    for (int k = 0; k < 3; ++k) q[k] = static_cast<std::uint32_t>(std::floor(double(c[k]) * 429496.7295 + 0.5));
    return {q[0] & 0xFFFFFFu, (q[0] >> 24) | ((q[1] & 0xFFFFu) << 8), (q[1] >> 16) | ((q[2] & 0xFFu) << 16), q[2] >> 8};
}

glm::vec3 decodeRgb32(glm::uvec4 codes) {
    std::uint32_t q[3] = {codes.x | (codes.y << 24), (codes.y >> 8) | (codes.z << 16), (codes.z >> 16) | (codes.w << 8)};
    glm::vec3 out;
    for (int k = 0; k < 3; ++k) out[k] = static_cast<float>(double(q[k]) * (10000.0 / 4294967295.0));
    return out;
}

glm::uvec4 encodeRgbe8(glm::vec3 rgb) {
    glm::vec3 c = sanitized(rgb, hdrRgbe8Max);
    float peak = peakOf(c);
    if (!(peak > 1e-32f)) return glm::uvec4(0u);
    int e = 0;
    std::frexp(peak, &e);
    // Ward's frexp mantissa · 256 / peak is exactly 2^(8 − e); scaling by it loses nothing.
    glm::uvec4 codes(0u, 0u, 0u, static_cast<std::uint32_t>(e + 128));
    for (int k = 0; k < 3; ++k) codes[k] = static_cast<std::uint32_t>(std::floor(std::ldexp(c[k], 8 - e)));
    return codes;
}

glm::vec3 decodeRgbe8(glm::uvec4 codes) {
    if (codes.w == 0u) return glm::vec3(0.0f);
    glm::vec3 out;
    for (int k = 0; k < 3; ++k) out[k] = std::ldexp(static_cast<float>(codes[k]) + 0.5f, static_cast<int>(codes.w) - 136);
    return out;
}

// The chapter's rgb · (1 + 64 a): the smallest alpha step whose multiplier covers the peak, so the
// peak channel keeps as many of its 8 bits as it can; above 65 the colour is scaled down keeping hue.
glm::uvec4 encodeRgba8x64(glm::vec3 rgb) {
    glm::vec3 c = sanitized(rgb, 1e30f);
    float peak = peakOf(c);
    if (peak > hdrRgba8x64Max) c *= hdrRgba8x64Max * (1.0f / peak);
    peak = std::min(peak, hdrRgba8x64Max);
    float alpha = peak > 1.0f ? std::min(std::ceil((peak - 1.0f) * (255.0f / 64.0f)), 255.0f) : 0.0f;
    float multiplier = 1.0f + 64.0f * (alpha * inv255);
    float inverse = 1.0f / multiplier;
    glm::uvec4 codes(0u, 0u, 0u, static_cast<std::uint32_t>(alpha));
    for (int k = 0; k < 3; ++k)
        codes[k] = static_cast<std::uint32_t>(roundHalfUp(std::clamp(c[k] * inverse, 0.0f, 1.0f) * 255.0f));
    return codes;
}

glm::vec3 decodeRgba8x64(glm::uvec4 codes) {
    return glm::vec3(codes) * inv255 * (1.0f + 64.0f * (static_cast<float>(codes.w) * inv255));
}

// What one code unit is worth in a texel channel; 0: the codes are the float's bits.
float codeUnit(HdrEncoding encoding) {
    switch (encoding) {
        case HdrEncoding::Float: return 0.0f;
        case HdrEncoding::Rgb16: return 65535.0f;
        case HdrEncoding::Rgb32: return 1.0f;
        default: return 255.0f;
    }
}

}  // namespace

std::optional<HdrEncoding> hdrEncodingFromIndex(int index) {
    if (index < 0 || index >= hdrEncodingCount) return std::nullopt;
    return static_cast<HdrEncoding>(index);
}

const char* hdrEncodingName(HdrEncoding encoding) {
    switch (encoding) {
        case HdrEncoding::Float: return "float";
        case HdrEncoding::Rgb16: return "RGB16";
        case HdrEncoding::Rgb32: return "RGB32";
        case HdrEncoding::Rgb9e5: return "RGB9E5";
        case HdrEncoding::Rgbe8: return "RGBE8";
        case HdrEncoding::Rgba8x64: return "RGBA8x64";
    }
    return "?";
}

TargetFormat hdrEncodingFormat(HdrEncoding encoding) {
    switch (encoding) {
        case HdrEncoding::Float:
        case HdrEncoding::Rgb32: return TargetFormat::RGBA32F;
        case HdrEncoding::Rgb16: return TargetFormat::RGBA16;
        default: return TargetFormat::RGBA8;
    }
}

float hdrEncodingMax(HdrEncoding encoding) {
    switch (encoding) {
        case HdrEncoding::Float: return std::numeric_limits<float>::max();
        case HdrEncoding::Rgb16: return hdrRgb16Max;
        case HdrEncoding::Rgb32: return hdrRgb32Max;
        case HdrEncoding::Rgb9e5: return hdrRgb9e5Max;
        case HdrEncoding::Rgbe8: return hdrRgbe8Max;
        case HdrEncoding::Rgba8x64: return hdrRgba8x64Max;
    }
    return 0.0f;
}

glm::uvec4 hdrTexelCodes(HdrEncoding encoding, glm::vec4 texel) {
    float unit = codeUnit(encoding);
    glm::uvec4 codes;
    for (int k = 0; k < 4; ++k) {
        if (unit == 0.0f) codes[k] = std::bit_cast<std::uint32_t>(texel[k]);
        else if (unit == 1.0f) codes[k] = static_cast<std::uint32_t>(std::clamp(texel[k], 0.0f, 16777215.0f));  // already integers
        else codes[k] = static_cast<std::uint32_t>(roundHalfUp(std::clamp(texel[k], 0.0f, 1.0f) * unit));
    }
    return codes;
}

glm::vec4 hdrCodesTexel(HdrEncoding encoding, glm::uvec4 codes) {
    float unit = codeUnit(encoding);
    glm::vec4 texel;
    for (int k = 0; k < 4; ++k)
        texel[k] = unit == 0.0f ? std::bit_cast<float>(codes[k]) : static_cast<float>(codes[k]) / unit;
    return texel;
}

glm::uvec4 encodeHdrCodes(HdrEncoding encoding, glm::vec3 rgb) {
    switch (encoding) {
        case HdrEncoding::Float: return hdrTexelCodes(encoding, glm::vec4(rgb, 1.0f));
        case HdrEncoding::Rgb16: return encodeRgb16(rgb);
        case HdrEncoding::Rgb32: return encodeRgb32(rgb);
        case HdrEncoding::Rgb9e5: return bytesOf(packRgb9e5(rgb));
        case HdrEncoding::Rgbe8: return encodeRgbe8(rgb);
        case HdrEncoding::Rgba8x64: return encodeRgba8x64(rgb);
    }
    return glm::uvec4(0u);
}

glm::vec3 decodeHdrCodes(HdrEncoding encoding, glm::uvec4 codes) {
    switch (encoding) {
        case HdrEncoding::Float: return glm::vec3(hdrCodesTexel(encoding, codes));
        case HdrEncoding::Rgb16: return decodeRgb16(codes);
        case HdrEncoding::Rgb32: return decodeRgb32(codes);
        case HdrEncoding::Rgb9e5: return unpackRgb9e5(wordOf(codes));
        case HdrEncoding::Rgbe8: return decodeRgbe8(codes);
        case HdrEncoding::Rgba8x64: return decodeRgba8x64(codes);
    }
    return glm::vec3(0.0f);
}

glm::vec4 encodeHdr(HdrEncoding encoding, glm::vec3 rgb) { return hdrCodesTexel(encoding, encodeHdrCodes(encoding, rgb)); }

glm::vec3 decodeHdr(HdrEncoding encoding, glm::vec4 texel) { return decodeHdrCodes(encoding, hdrTexelCodes(encoding, texel)); }

std::uint32_t packRgb9e5(glm::vec3 rgb) {
    glm::vec3 c = sanitized(rgb, hdrRgb9e5Max);
    float peak = peakOf(c);
    // floor(log2(peak)) exactly, from frexp rather than an approximate log2; at least -16.
    int log2Peak = -16;
    if (peak >= 0x1p-16f) {
        std::frexp(peak, &log2Peak);
        log2Peak -= 1;
    }
    int e = log2Peak + 16;  // the biased shared exponent: floor(log2) + 1 + 15; a mantissa step is 2^(e − 24)
    if (roundHalfUp(std::ldexp(peak, 24 - e)) == 512.0f) ++e;
    std::uint32_t bits = static_cast<std::uint32_t>(e) << 27;
    for (int k = 0; k < 3; ++k) bits |= static_cast<std::uint32_t>(roundHalfUp(std::ldexp(c[k], 24 - e))) << (9 * k);
    return bits;
}

glm::vec3 unpackRgb9e5(std::uint32_t bits) {
    int e = static_cast<int>(bits >> 27);
    glm::vec3 out;
    for (int k = 0; k < 3; ++k) out[k] = std::ldexp(static_cast<float>((bits >> (9 * k)) & 511u), e - 24);
    return out;
}

}  // namespace rmfx
