#include "bench/accuracy/IdealBloom.h"

#include <algorithm>
#include <cmath>

namespace rmfx::accuracy {

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

LinearImage separableBlur(const LinearImage& image, const std::vector<double>& kernel) {
    const int radius = static_cast<int>(kernel.size() / 2);
    const int w = image.width, h = image.height;
    LinearImage horizontal(w, h), out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int i = std::max(-radius, -x); i <= std::min(radius, w - 1 - x); ++i) {
                double k = kernel[i + radius];
                for (int c = 0; c < 3; ++c) horizontal.at(x, y, c) += k * image.at(x + i, y, c);
            }
    for (int y = 0; y < h; ++y)
        for (int i = std::max(-radius, -y); i <= std::min(radius, h - 1 - y); ++i) {
            double k = kernel[i + radius];
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c) out.at(x, y, c) += k * horizontal.at(x, y + i, c);
        }
    return out;
}

LinearImage brightPass(const LinearImage& sanitised, double threshold) {
    LinearImage out = sanitised;
    for (double& v : out.rgb) v = std::max(v - threshold, 0.0);
    return out;
}

LinearImage idealBloom(const LinearImage& sanitised, const BloomParameters& p) {
    LinearImage blurred = separableBlur(brightPass(sanitised, p.threshold), gaussianKernel(p.sigma * sanitised.height));
    LinearImage out = sanitised;
    for (size_t i = 0; i < out.rgb.size(); ++i) out.rgb[i] += p.strength * blurred.rgb[i];
    return out;
}

}  // namespace rmfx::accuracy
