#include "reference/IdealBloom.h"

#include <algorithm>
#include <cmath>

namespace rmfx::test {

std::vector<double> gaussianKernel(double sigmaPixels) {
    if (!(sigmaPixels > 0.0)) return {1.0};
    int radius = static_cast<int>(std::ceil(4.0 * sigmaPixels));
    std::vector<double> kernel(2 * radius + 1);
    double sum = 0.0;
    for (int i = -radius; i <= radius; ++i) {
        kernel[i + radius] = std::exp(-0.5 * i * i / (sigmaPixels * sigmaPixels));
        sum += kernel[i + radius];
    }
    for (double& w : kernel) w /= sum;
    return kernel;
}

RefImage separableBlur(const RefImage& image, const std::vector<double>& kernel) {
    const int radius = static_cast<int>(kernel.size() / 2);
    const int w = image.width, h = image.height;
    RefImage horizontal(w, h), out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int i = std::max(-radius, -x); i <= std::min(radius, w - 1 - x); ++i) {
                double k = kernel[i + radius];
                for (int c = 0; c < 3; ++c) horizontal.at(x, y)[c] += k * image.at(x + i, y)[c];
            }
    // Σ_i k[i] · horizontal(x, y − i): the taps summed from the top row down (rows are bottom-up),
    // the order the bench's float64 sums have always taken, so that its results stay bit-identical.
    for (int y = 0; y < h; ++y)
        for (int i = std::max(-radius, y - (h - 1)); i <= std::min(radius, y); ++i) {
            double k = kernel[i + radius];
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c) out.at(x, y)[c] += k * horizontal.at(x, y - i)[c];
        }
    return out;
}

RefImage brightPass(const RefImage& sanitised, double threshold) {
    RefImage out = sanitised;
    for (glm::dvec4& t : out.texels)
        for (int c = 0; c < 3; ++c) t[c] = std::max(t[c] - threshold, 0.0);
    return out;
}

RefImage idealBloom(const RefImage& sanitised, const BloomParameters& p) {
    RefImage blurred = separableBlur(brightPass(sanitised, p.threshold), gaussianKernel(p.sigma * sanitised.height));
    RefImage out = sanitised;
    for (size_t i = 0; i < out.texels.size(); ++i)
        for (int c = 0; c < 3; ++c) out.texels[i][c] += p.strength * blurred.texels[i][c];
    return out;
}

}  // namespace rmfx::test
