#include "editor/TargetDecoding.h"

#include <algorithm>
#include <cmath>

#include "io/image/ImageIO.h"

namespace rmfx::editor {
namespace {

HdrEncoding encodingOf(DecodeAs decode) {
    switch (decode) {
        case DecodeAs::Rgbe8: return HdrEncoding::Rgbe8;
        case DecodeAs::Rgb9e5: return HdrEncoding::Rgb9e5;
        case DecodeAs::Rgba8x64: return HdrEncoding::Rgba8x64;
        case DecodeAs::Rgb16: return HdrEncoding::Rgb16;
        case DecodeAs::Rgb32: return HdrEncoding::Rgb32;
        case DecodeAs::None: break;
    }
    return HdrEncoding::Float;
}

std::uint8_t displayByte(float v, DisplayTransform transform) {
    v = std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f);
    if (transform == DisplayTransform::Srgb) v = std::clamp(srgbEncode(v), 0.0f, 1.0f);
    return static_cast<std::uint8_t>(std::lround(v * 255.0f));
}

}  // namespace

const char* decodeAsLabel(DecodeAs decode) {
    switch (decode) {
        case DecodeAs::None: return "none";
        case DecodeAs::Rgbe8: return "RGBE8";
        case DecodeAs::Rgb9e5: return "RGB9E5";
        case DecodeAs::Rgba8x64: return "alpha x64";
        case DecodeAs::Rgb16: return "RGB16";
        case DecodeAs::Rgb32: return "RGB32";
    }
    return "?";
}

glm::vec4 texelAt(const Image& image, int x, int y) {
    if (image.channels == 1) return {image.at(x, y, 0), 0.0f, 0.0f, 1.0f};
    glm::vec4 t(0.0f, 0.0f, 0.0f, 1.0f);
    for (int c = 0; c < std::min(image.channels, 4); ++c) t[c] = image.at(x, y, c);
    return t;
}

glm::vec4 decodeTexel(DecodeAs decode, glm::vec4 texel) {
    if (decode == DecodeAs::None) return texel;
    return glm::vec4(decodeHdr(encodingOf(decode), texel), 1.0f);
}

std::array<std::uint8_t, 4> displayBytes(glm::vec4 linear, float exposureStops, DisplayTransform transform) {
    const float scale = std::exp2(exposureStops);
    return {displayByte(linear.r * scale, transform), displayByte(linear.g * scale, transform),
            displayByte(linear.b * scale, transform), 255};
}

std::vector<std::uint8_t> displayPixels(const Image& image, DecodeAs decode, float exposureStops, DisplayTransform transform) {
    std::vector<std::uint8_t> out(static_cast<size_t>(image.width) * image.height * 4);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            auto bytes = displayBytes(decodeTexel(decode, texelAt(image, x, y)), exposureStops, transform);
            std::copy(bytes.begin(), bytes.end(), out.begin() + (static_cast<size_t>(y) * image.width + x) * 4);
        }
    return out;
}

}  // namespace rmfx::editor
