#pragma once
// A float64 RGB image for the bench's ideals and metrics: row 0 at the top, as runtime Image.

#include <cstddef>
#include <vector>

#include "model/Image.h"

namespace rmfx::accuracy {

struct LinearImage {
    int width = 0;
    int height = 0;
    std::vector<double> rgb;  // width * height * 3

    LinearImage() = default;
    LinearImage(int w, int h) : width(w), height(h), rgb(static_cast<size_t>(w) * h * 3, 0.0) {}

    double& at(int x, int y, int c) { return rgb[(static_cast<size_t>(y) * width + x) * 3 + c]; }
    double at(int x, int y, int c) const { return rgb[(static_cast<size_t>(y) * width + x) * 3 + c]; }
    size_t pixelCount() const { return static_cast<size_t>(width) * height; }
};

// Rec.709 luminance.
inline double luminance(double r, double g, double b) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }
inline double luminanceAt(const LinearImage& image, int x, int y) {
    return luminance(image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2));
}

// The contract's sanitising of an input: NaN, ±Inf and negative channels become 0. One channel
// is grey (copied to r, g, b); two channels leave b at 0; alpha is dropped.
LinearImage sanitisedInput(const Image& image);

// The image's rgb as it is (no sanitising), for GPU read-backs.
LinearImage linearImageOf(const Image& image);

}  // namespace rmfx::accuracy
