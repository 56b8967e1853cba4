#include "reference/GhostReference.h"

namespace rmfx::test {

RefImage ghostPass(const RefImage& source, const RefImage& mask, int width, int height, double glowFactor) {
    return shadePixels(width, height, [&](glm::dvec2 uv) {
        glm::dvec4 sum(0.0);
        for (double s : kGhostScales) {
            glm::dvec2 c = (uv - 0.5) * s + 0.5;
            sum += sampleBilinear(source, c) * sampleBilinear(mask, c).a;
        }
        return sum * glowFactor;
    });
}

std::array<RefImage, 2> ghostChain(const RefImage& scene, const RefImage& mask, glm::ivec2 size, double glowFactor,
                                   TargetRounding rounding) {
    RefImage first = roundedTo(ghostPass(scene, mask, size.x, size.y, glowFactor), rounding);
    RefImage second = roundedTo(ghostPass(first, mask, size.x, size.y, glowFactor), rounding);
    return {first, second};
}

RefImage ghostComposite(const RefImage& ghosts, int width, int height) {
    return shadePixels(width, height,
                       [&](glm::dvec2 uv) { return glm::dvec4(glm::dvec3(sampleBilinear(ghosts, uv)), 0.8); });
}

std::vector<glm::dvec2> ghostPositions(glm::dvec2 light, int passes) {
    std::vector<double> scales{1.0};
    for (int p = 0; p < passes; ++p) {
        std::vector<double> next;
        for (double a : scales)
            for (double s : kGhostScales) next.push_back(a * s);
        scales = next;
    }
    std::vector<glm::dvec2> positions;
    for (double s : scales) positions.push_back(0.5 + (light - 0.5) / s);
    return positions;
}

}  // namespace rmfx::test
