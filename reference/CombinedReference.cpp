#include "reference/CombinedReference.h"

#include "reference/GlareReference.h"

namespace rmfx::test {

CombinedTerms allCombineTerms(const RefImage& ghosts, const std::array<RefImage, 3>& glare, glm::dvec3 glowFactors,
                              const std::array<RefImage, 4>& streaks, double streakFactor, int width, int height) {
    CombinedTerms terms;
    terms.glare = glareCombine(glare[0], glare[1], glare[2], glowFactors, width, height, false);
    terms.ghosts = shadePixels(width, height, [&](glm::dvec2 uv) {
        return glm::dvec4(glm::dvec3(sampleBilinear(ghosts, uv)), 0.0);
    });
    terms.streaks = shadePixels(width, height, [&](glm::dvec2 uv) {
        glm::dvec3 sum(0.0);
        for (const RefImage& streak : streaks) sum += glm::dvec3(sampleBilinear(streak, uv)) * streakFactor;
        return glm::dvec4(sum, 0.0);
    });
    return terms;
}

RefImage allCombine(const CombinedTerms& terms) {
    RefImage sum = terms.glare;
    for (size_t t = 0; t < sum.texels.size(); ++t) sum.texels[t] += terms.ghosts.texels[t] + terms.streaks.texels[t];
    return sum;
}

}  // namespace rmfx::test
