#pragma once
// HDR colour in integer target formats: the C++ twins of effects/glsl/hdr_encoding.glsl, for
// decoding targets on the CPU (the editor's display, tests) and encoding media. Where the maths
// is integer (every encoding but Float) a twin gives the same bits as the shader; the encodings,
// their ranges and measured errors are in docs/encodings.md.

#include <cstdint>
#include <optional>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "model/Workspace.h"

namespace rmfx {

// The values of the GLSL selector `HDR_Encoding`, in order.
enum class HdrEncoding { Float, Rgb16, Rgb32, Rgb9e5, Rgbe8, Rgba8x64 };
inline constexpr int hdrEncodingCount = 6;

std::optional<HdrEncoding> hdrEncodingFromIndex(int index);
const char* hdrEncodingName(HdrEncoding encoding);  // "float", "RGB16", …, "RGBA8x64"
// The target format an encoding's texels need: rgba16 (RGB16), rgba32f holding four 24-bit
// integers (RGB32), rgba8 (the byte encodings), rgba32f for Float (any float format works).
TargetFormat hdrEncodingFormat(HdrEncoding encoding);

// Every channel of a texel is an integer code: k / 255 in rgba8, k / 65535 in rgba16, an integer
// below 2^24 in rgba32f (Float: the float's bits). Codes are what the twins compare exactly.
glm::uvec4 hdrTexelCodes(HdrEncoding encoding, glm::vec4 texel);
glm::vec4 hdrCodesTexel(HdrEncoding encoding, glm::uvec4 codes);

// The codes a shader's encodeHDR writes for linear rgb, and the rgb its decodeHDR reads back.
glm::uvec4 encodeHdrCodes(HdrEncoding encoding, glm::vec3 rgb);
glm::vec3 decodeHdrCodes(HdrEncoding encoding, glm::uvec4 codes);

// The same on texels as a target stores them (readTarget, texelFetch).
glm::vec4 encodeHdr(HdrEncoding encoding, glm::vec3 rgb);
glm::vec3 decodeHdr(HdrEncoding encoding, glm::vec4 texel);

// The largest value each encoding keeps; larger ones saturate to it (per channel, or scaled
// keeping hue for RGBA8x64). hdrEncodingMax(Float) is the largest float.
inline constexpr float hdrRgb16Max = 100.0f;
inline constexpr float hdrRgb32Max = 10000.0f;
inline constexpr float hdrRgb9e5Max = 65408.0f;             // 511/512 · 2^16
inline constexpr float hdrRgbe8Max = 0x1.fep126f;  // 255 · 2^119 ≈ 1.69e38: exponent byte 255, mantissa 255
inline constexpr float hdrRgba8x64Max = 65.0f;
float hdrEncodingMax(HdrEncoding encoding);

// RGB9E5 as one 32-bit word: mantissas in bits 0-8, 9-17, 18-26, the exponent in 27-31
// (EXT_texture_shared_exponent's layout); in an rgba8 texel byte i holds bits 8i..8i+7.
std::uint32_t packRgb9e5(glm::vec3 rgb);
glm::vec3 unpackRgb9e5(std::uint32_t bits);

}  // namespace rmfx
