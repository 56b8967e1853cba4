#pragma once
// Float64 references of the HDR encodings, written from their definitions (EXT_texture_shared_exponent,
// Ward's Radiance RGBE, HDRFormats' linear RGB16 / RGB32, the chapter's rgb · (1 + 64 a)), independently
// of runtime/HdrEncoding.cpp: the integer codes each definition stores for a colour and the colour
// it decodes to. Inputs are sanitised as the encodings document: NaN and negatives to 0, values
// above the maximum to the maximum.

#include <cstdint>

#include <glm/vec3.hpp>

#include "model/HdrEncoding.h"

namespace rmfx::test {

struct RefEncoded {
    std::uint64_t codes[4] = {0, 0, 0, 0};  // RGB16: 3 × 16 bits; RGB32: 3 × 32 bits; RGB9E5: 3 mantissas, exponent; RGBE8 / RGBA8x64: 4 bytes
    glm::dvec3 decoded{0.0};
};

RefEncoded referenceEncode(HdrEncoding encoding, glm::dvec3 rgb);

// The error bound each format guarantees for a colour (before float rounding of the decoded
// value): RGB16 and RGB32 half a step absolute, RGB9E5 1/511.5 (2^-9 · 512/511.5) and RGBE8 2^-8 of
// the largest channel (RGB9E5 at least half its smallest step 2^-24), RGBA8x64 half an 8-bit step
// times the multiplier.
double referenceErrorBound(HdrEncoding encoding, glm::dvec3 rgb);

}  // namespace rmfx::test
