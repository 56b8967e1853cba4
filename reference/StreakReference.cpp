#include "reference/StreakReference.h"

#include <cmath>

#include <glm/common.hpp>

namespace rmfx::test {

RefImage streakPass(const RefImage& source, int width, int height, glm::dvec2 direction, double offsetFactor) {
    glm::dvec2 texel(1.0 / width, 1.0 / height);
    return shadePixels(width, height, [&](glm::dvec2 uv) {
        glm::dvec4 sum(0.0);
        for (int i = 0; i < 4; ++i)
            sum += std::pow(kStreakBlurFactor, offsetFactor * i) *
                   sampleBilinear(source, uv + offsetFactor * i * direction * texel);
        return sum;
    });
}

std::array<RefImage, 2> streakChain(const RefImage& scene, glm::ivec2 size, glm::dvec2 direction,
                                    TargetRounding rounding) {
    RefImage first = roundedTo(streakPass(scene, size.x, size.y, direction, 1.0), rounding);
    RefImage second = roundedTo(streakPass(first, size.x, size.y, direction, 4.0), rounding);
    return {first, second};
}

RefImage streakCombine(const std::array<RefImage, 4>& streaks, double glowFactor, int width, int height,
                       bool alpha64) {
    return shadePixels(width, height, [&](glm::dvec2 uv) {
        glm::dvec4 sum(0.0);
        for (const RefImage& streak : streaks) {
            glm::dvec4 texel = sampleBilinear(streak, uv);
            glm::dvec3 color = alpha64 ? decodeAlpha64(texel) : glm::dvec3(texel);
            sum += glm::dvec4(color * glowFactor, 0.15);
        }
        return glm::min(sum, glm::dvec4(1.0));
    });
}

}  // namespace rmfx::test
