#include "reference/StageInput.h"

#include <cmath>
#include <random>

namespace rmfx::test {
namespace {

double sanitisedChannel(double c) { return std::isfinite(c) && c > 0.0 ? c : 0.0; }

}  // namespace

glm::dvec3 sanitisedTexel(glm::dvec4 texel) {
    return {sanitisedChannel(texel.r), sanitisedChannel(texel.g), sanitisedChannel(texel.b)};
}

double rec709Luminance(glm::dvec3 rgb) { return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b; }

RefImage sanitisedInput(const Image& image) {
    RefImage out = fromImage(image);
    for (glm::dvec4& texel : out.texels) texel = glm::dvec4(sanitisedTexel(texel), texel.a);
    return out;
}

RefImage syntheticHdrImage(int width, int height, unsigned seed, double minLog2, double maxLog2, double black,
                           double binWidthLog2) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    RefImage image(width, height);
    for (glm::dvec4& texel : image.texels) {
        double log2Y = minLog2 + (maxLog2 - minLog2) * unit(random);
        if (binWidthLog2 > 0.0) {
            double bin = std::floor((log2Y - minLog2) / binWidthLog2);
            log2Y = minLog2 + (bin + 0.5 + 0.6 * (unit(random) - 0.5)) * binWidthLog2;
        }
        glm::dvec3 chroma(0.2 + unit(random), 0.2 + unit(random), 0.2 + unit(random));
        double y = unit(random) < black ? 0.0 : std::exp2(log2Y);
        // Rounded to float here, so that the luminance the references see is that of the texel.
        glm::dvec3 rgb = glm::dvec3(glm::vec3(chroma * (y / rec709Luminance(chroma))));
        texel = glm::dvec4(rgb, 1.0);
    }
    return image;
}

}  // namespace rmfx::test
