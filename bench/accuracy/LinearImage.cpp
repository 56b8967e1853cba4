#include "bench/accuracy/LinearImage.h"

#include <cmath>

namespace rmfx::accuracy {
namespace {

double finiteNonNegative(float v) { return std::isfinite(v) && v > 0.0f ? static_cast<double>(v) : 0.0; }

LinearImage convert(const Image& image, bool sanitise) {
    LinearImage out(image.width, image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) {
                int source = image.channels == 1 ? 0 : c;
                float v = source < image.channels ? image.at(x, y, source) : 0.0f;
                out.at(x, y, c) = sanitise ? finiteNonNegative(v) : static_cast<double>(v);
            }
    return out;
}

}  // namespace

LinearImage sanitisedInput(const Image& image) { return convert(image, true); }
LinearImage linearImageOf(const Image& image) { return convert(image, false); }

}  // namespace rmfx::accuracy
