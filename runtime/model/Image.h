#pragma once
// A CPU image: interleaved float channels, row 0 at the top (as image files store it).

#include <array>
#include <cstddef>
#include <vector>

namespace rmfx {

struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;           // 1..4
    bool highDynamicRange = false;  // file held float/half data; false: 8/16-bit integer data
    int bitsPerChannel = 32;    // of the source file: 8, 16, 32 (half reads as 16)
    std::vector<float> pixels;  // width * height * depth * channels; integer files as value / max (no colour conversion)
    int depth = 1;              // slices of a volume (3D) image, each width x height, slice 0 first (last: positional initialisers)

    float& at(int x, int y, int c) { return pixels[(static_cast<size_t>(y) * width + x) * channels + c]; }
    float at(int x, int y, int c) const { return pixels[(static_cast<size_t>(y) * width + x) * channels + c]; }
    bool empty() const { return pixels.empty(); }
};

// What becomes of colour values written to an integer image format (alpha is never changed).
enum class DisplayTransform {
    None,  // the values as they are, clamped to [0, 1]
    Srgb,  // encoded with the sRGB transfer function (IEC 61966-2-1)
};

// The six faces of a cube map in OpenGL order: +X, -X, +Y, -Y, +Z, -Z, each seen as OpenGL's
// cube-map face convention expects (row 0 at the top of the face as sampled with that convention).
using CubeFaces = std::array<Image, 6>;

}  // namespace rmfx
