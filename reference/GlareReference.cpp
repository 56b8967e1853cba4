#include "reference/GlareReference.h"

#include <array>

namespace rmfx::test {

std::vector<KernelTap> gauss9Kernel() {
    // The chapter's table in its order, its first row corrected from (-1, 1) to (-1, -1).
    return {{{-1, -1}, 1.0 / 16}, {{-1, 1}, 1.0 / 16}, {{1, -1}, 1.0 / 16}, {{1, 1}, 1.0 / 16},
            {{-1, 0}, 2.0 / 16},  {{1, 0}, 2.0 / 16},  {{0, -1}, 2.0 / 16}, {{0, 1}, 2.0 / 16},
            {{0, 0}, 4.0 / 16}};
}

std::vector<KernelTap> gauss49Kernel() {
    const std::array<double, 7> binomial{1, 6, 15, 20, 15, 6, 1};
    std::vector<KernelTap> taps;
    for (int y = -3; y <= 3; ++y)
        for (int x = -3; x <= 3; ++x)
            taps.push_back({{x, y}, binomial[x + 3] * binomial[y + 3] / 4096.0});
    return taps;
}

glm::dvec2 kernelVariance(const std::vector<KernelTap>& kernel) {
    double total = 0.0;
    glm::dvec2 mean(0.0), square(0.0);
    for (const KernelTap& t : kernel) {
        total += t.weight;
        mean += t.weight * t.offset;
        square += t.weight * t.offset * t.offset;
    }
    mean /= total;
    return square / total - mean * mean;
}

RefImage blurPass(const RefImage& source, int width, int height, const std::vector<KernelTap>& kernel) {
    glm::dvec2 texel(1.0 / width, 1.0 / height);
    return shadePixels(width, height, [&](glm::dvec2 uv) {
        glm::dvec4 sum(0.0);
        for (const KernelTap& t : kernel) sum += t.weight * sampleBilinear(source, uv + t.offset * texel);
        return sum;
    });
}

std::vector<RefImage> blurChain(const RefImage& scene, glm::ivec2 size, const std::vector<KernelTap>& kernel,
                                int passes, TargetRounding rounding) {
    std::vector<RefImage> levels;
    for (int i = 0; i < passes; ++i)
        levels.push_back(roundedTo(blurPass(i == 0 ? scene : levels.back(), size.x, size.y, kernel), rounding));
    return levels;
}

std::vector<RefImage> blurChainFilteringBounds(const RefImage& scene, const std::vector<RefImage>& levels, glm::ivec2 size,
                                               const std::vector<KernelTap>& kernel, double weightError) {
    std::vector<RefImage> bounds;
    const glm::dvec2 texel(1.0 / size.x, 1.0 / size.y);
    for (size_t k = 0; k < levels.size(); ++k) {
        const RefImage& source = k == 0 ? scene : levels[k - 1];
        bounds.push_back(shadePixels(size.x, size.y, [&](glm::dvec2 uv) {
            glm::dvec4 sum(0.0);
            for (const KernelTap& t : kernel) {
                const glm::dvec2 at = uv + t.offset * texel;
                glm::dvec4 tap = 2.0 * weightError * bilinearFootprintRange(source, at);
                if (k > 0) tap += sampleBilinear(bounds[k - 1], at);
                sum += t.weight * tap;
            }
            return sum;
        }));
    }
    return bounds;
}

RefImage glareCombineFilteringBound(const RefImage& level0, const RefImage& level1, const RefImage& level2,
                                    const RefImage& bound0, const RefImage& bound1, const RefImage& bound2,
                                    glm::dvec3 glowFactors, int width, int height, double weightError) {
    const RefImage* levels[3] = {&level0, &level1, &level2};
    const RefImage* bounds[3] = {&bound0, &bound1, &bound2};
    return shadePixels(width, height, [&](glm::dvec2 uv) {
        glm::dvec4 sum(0.0);
        for (int j = 0; j < 3; ++j)
            sum += glowFactors[j] * (2.0 * weightError * bilinearFootprintRange(*levels[j], uv) + sampleBilinear(*bounds[j], uv));
        return glm::dvec4(glm::dvec3(sum), 0.0);
    });
}

RefImage glareCombine(const RefImage& level0, const RefImage& level1, const RefImage& level2,
                      glm::dvec3 glowFactors, int width, int height, bool alpha64) {
    auto level = [alpha64](const RefImage& image, glm::dvec2 uv) {
        glm::dvec4 c = sampleBilinear(image, uv);
        return alpha64 ? decodeAlpha64(c) : glm::dvec3(c);
    };
    return shadePixels(width, height, [&](glm::dvec2 uv) {
        glm::dvec3 rgb = level(level0, uv) * glowFactors[0] + level(level1, uv) * glowFactors[1] +
                         level(level2, uv) * glowFactors[2];
        return glm::dvec4(rgb, 1.0);
    });
}

ImageMoments imageMoments(const RefImage& image, int channel) {
    ImageMoments m;
    glm::dvec2 square(0.0);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            double w = image.at(x, y)[channel];
            glm::dvec2 p(x, y);
            m.total += w;
            m.mean += w * p;
            square += w * p * p;
        }
    m.mean /= m.total;
    m.variance = square / m.total - m.mean * m.mean;
    return m;
}

}  // namespace rmfx::test
