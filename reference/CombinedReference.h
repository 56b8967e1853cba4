#pragma once
// Float64 reference of the chapter-8 composite of all the effects (shader_5), written from the
// chapter's shader_5 code: the ghosts as they are, the three glare levels weighted by Glow_Factor,
// Glow_Factor2 and Glow_Factor3, and the four streaks weighted by Streak_Factor, summed with alpha 1.

#include <array>

#include <glm/vec3.hpp>

#include "reference/CpuImage.h"

namespace rmfx::test {

// The composite's three terms at each pixel centre of a width x height screen, every target
// sampled bilinearly: the glare (Σ Glow_Factor_i · glare_i.rgb, 1) (glareCombine), the ghosts
// (ghosts.rgb, 0) and the streaks (Streak_Factor · Σ_k streak_k.rgb, 0). Not rounded.
struct CombinedTerms {
    RefImage glare;
    RefImage ghosts;
    RefImage streaks;
};
CombinedTerms allCombineTerms(const RefImage& ghosts, const std::array<RefImage, 3>& glare, glm::dvec3 glowFactors,
                              const std::array<RefImage, 4>& streaks, double streakFactor, int width, int height);

// Their sum, what the chapter's shader_5 composite returns. Not rounded.
RefImage allCombine(const CombinedTerms& terms);

}  // namespace rmfx::test
