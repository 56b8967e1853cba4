#include "reference/ArticleReference.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace rmfx::test::article {

RefImage downsampleSuppressLdr(const RefImage& scene, int width, int height, glm::dvec3 kd) {
    return shadePixels(width, height, [&](glm::dvec2 uv) {
        glm::dvec4 c = sampleBilinear(scene, uv) * glm::dvec4(kd, 1.0);
        return (c.r > 1.0 || c.g > 1.0 || c.b > 1.0) ? c : glm::dvec4(0.0);
    });
}

double blurWeight(int offset) {
    int k = 8 + std::abs(offset);
    if (k > 16) return 0.0;
    double binomial = 1.0;
    for (int i = 1; i <= k; ++i) binomial = binomial * (16 - k + i) / i;  // C(16, k)
    return binomial / 65536.0;
}

RefImage blur17(const RefImage& image, int dx, int dy) {
    RefImage out(image.width, image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            glm::dvec4 sum(0.0);
            for (int i = -8; i <= 8; ++i) sum += fetchClamped(image, x + i * dx, y + i * dy) * blurWeight(i);
            out.at(x, y) = sum;
        }
    return out;
}

glm::dvec3 toneMap(glm::dvec3 original, glm::dvec3 blur, glm::dvec2 uv, double exposure) {
    glm::dvec3 color = glm::mix(original, blur, 0.4);
    glm::dvec2 fromCentre = uv - 0.5;
    color *= std::pow(1.0 - glm::dot(fromCentre, fromCentre), 4.0) * exposure;
    return glm::pow(glm::max(color, 0.0), glm::dvec3(0.55));
}

}  // namespace rmfx::test::article
