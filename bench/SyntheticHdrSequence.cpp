#include "bench/SyntheticHdrSequence.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "io/image/ImageIO.h"
#include "io/media/ImageSequence.h"

namespace rmfx::bench {
namespace {

// A light that circles its centre; positions and sizes in fractions of the image's height, so
// the picture keeps its look at any size.
struct Light {
    float centreX, centreY;  // centreX in fractions of the width
    float orbit;             // radius of the circle
    float turnsPerFrame;
    float sigma;             // of the Gaussian spot
    float radiance;          // at its peak
    float red, green, blue;
};

constexpr Light kLights[] = {
    {0.25f, 0.30f, 0.10f, 0.011f, 0.006f, 2000.0f, 1.0f, 0.8f, 0.5f},
    {0.70f, 0.25f, 0.05f, -0.017f, 0.004f, 600.0f, 0.5f, 0.7f, 1.0f},
    {0.50f, 0.60f, 0.20f, 0.007f, 0.010f, 150.0f, 1.0f, 1.0f, 1.0f},
    {0.85f, 0.70f, 0.08f, 0.023f, 0.003f, 1200.0f, 1.0f, 0.5f, 0.3f},
    {0.15f, 0.75f, 0.12f, -0.009f, 0.008f, 60.0f, 0.6f, 1.0f, 0.6f},
};

std::uint32_t hash(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

// In [-1, 1).
float noise(int x, int y, int frame) {
    std::uint32_t h = hash(static_cast<std::uint32_t>(x) + hash(static_cast<std::uint32_t>(y) + hash(static_cast<std::uint32_t>(frame))));
    return static_cast<float>(h) / 2147483648.0f - 1.0f;
}

}  // namespace

Image syntheticHdrFrame(int frame, glm::ivec2 size) {
    Image image;
    image.width = size.x;
    image.height = size.y;
    image.channels = 4;
    image.highDynamicRange = true;
    image.bitsPerChannel = 16;
    image.pixels.assign(static_cast<size_t>(size.x) * size.y * 4, 0.0f);
    const float h = static_cast<float>(size.y);

    // A dim gradient, brighter towards the top, a glowing panel just above the bright pass, and
    // a few per cent of noise.
    for (int y = 0; y < size.y; ++y) {
        const float up = 1.0f - y / h;
        for (int x = 0; x < size.x; ++x) {
            const float u = x / static_cast<float>(size.x);
            const bool panel = u > 0.40f && u < 0.60f && up > 0.80f && up < 0.90f;
            const float base = panel ? 8.0f : 0.03f + 0.3f * up * up;
            const float grain = 1.0f + 0.04f * noise(x, y, frame);
            image.at(x, y, 0) = base * 1.00f * grain;
            image.at(x, y, 1) = base * 0.90f * grain;
            image.at(x, y, 2) = base * 0.75f * grain;
            image.at(x, y, 3) = 1.0f;
        }
    }
    for (const Light& light : kLights) {
        const float angle = 6.2831853f * light.turnsPerFrame * static_cast<float>(frame);
        const float cx = light.centreX * size.x + light.orbit * h * std::cos(angle);
        const float cy = light.centreY * h + light.orbit * h * std::sin(angle);
        const float sigma = std::max(0.5f, light.sigma * h);
        const float reach = 4.0f * sigma;  // beyond it the spot adds under 1/2980 of its peak
        const int x0 = std::max(0, static_cast<int>(std::floor(cx - reach)));
        const int x1 = std::min(size.x - 1, static_cast<int>(std::ceil(cx + reach)));
        const int y0 = std::max(0, static_cast<int>(std::floor(cy - reach)));
        const int y1 = std::min(size.y - 1, static_cast<int>(std::ceil(cy + reach)));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const float dx = x + 0.5f - cx, dy = y + 0.5f - cy;
                const float spot = light.radiance * std::exp(-(dx * dx + dy * dy) / (2.0f * sigma * sigma));
                image.at(x, y, 0) += spot * light.red;
                image.at(x, y, 1) += spot * light.green;
                image.at(x, y, 2) += spot * light.blue;
            }
    }
    return image;
}

Result<std::string> writeSyntheticHdrSequence(const std::filesystem::path& folder, int count, glm::ivec2 size) {
    const std::string pattern = (folder / "frame.%04d.exr").string();
    WriteOptions half;
    half.exrHalf = true;
    for (int k = 0; k < count; ++k) {
        if (Result<void> written = writeImage(frameFileName(pattern, k), syntheticHdrFrame(k, size), half); !written)
            return Error{written.error()};
    }
    return pattern;
}

}  // namespace rmfx::bench
