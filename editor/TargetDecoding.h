#pragma once
// What the render-target viewer shows: a texel as the target stores it, decoded from an HDR
// encoding chosen in the viewer ("decode as"), scaled by an exposure in stops and encoded to sRGB
// bytes. Pure CPU code on Images from GlExecutor::readTarget, unit-tested.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "model/HdrEncoding.h"
#include "model/Image.h"

namespace rmfx::editor {

// The viewer's "decode as" choices, in combo order.
enum class DecodeAs { None, Rgbe8, Rgb9e5, Rgba8x64, Rgb16, Rgb32 };
inline constexpr int decodeAsCount = 6;
const char* decodeAsLabel(DecodeAs decode);  // "none", "RGBE8", "RGB9E5", "alpha x64", "RGB16", "RGB32"

// The texel at (x, y) (row 0 at the top) as GL samples it: one-channel images give (r, 0, 0, 1).
glm::vec4 texelAt(const Image& image, int x, int y);

// The linear colour a texel stands for: None keeps the texel; an encoding decodes rgb with the
// runtime's twin of the shader's decodeHDR (runtime/HdrEncoding.h) and gives alpha 1, since the
// encodings spend alpha on the colour.
glm::vec4 decodeTexel(DecodeAs decode, glm::vec4 texel);

// linear × 2^exposureStops, clamped to [0, 1] (NaN to 0), through the display transform (sRGB
// for linear data) and rounded to bytes, as `rmfx render` quantises a PNG. Alpha is 255: the
// viewer shows colour.
std::array<std::uint8_t, 4> displayBytes(glm::vec4 linear, float exposureStops,
                                         DisplayTransform transform = DisplayTransform::Srgb);

// displayBytes of every decoded texel: RGBA8, row 0 at the top.
std::vector<std::uint8_t> displayPixels(const Image& image, DecodeAs decode, float exposureStops,
                                        DisplayTransform transform = DisplayTransform::Srgb);

}  // namespace rmfx::editor
