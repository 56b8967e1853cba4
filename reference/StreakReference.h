#pragma once
// Float64 reference of the chapter-8 streaks (shader_3, exercise 2), written from the chapter's
// definitions: the 4-sample diagonal filter, the two passes of one direction with the rounding of
// the targets they write, and the composite of the four directions.

#include <array>

#include <glm/vec2.hpp>

#include "reference/CpuImage.h"

namespace rmfx::test {

inline constexpr double kStreakBlurFactor = 0.96;

// One streak pass into a width x height target: at each pixel centre uv, the sum over i = 0..3 of
// blurFactor^(offsetFactor · i) · bilinear(source, uv + offsetFactor · i · direction / (width,
// height)), clamp-to-edge addressing. `direction` is (±1, ±1) in texture space. Not rounded.
RefImage streakPass(const RefImage& source, int width, int height, glm::dvec2 direction, double offsetFactor);

// The two passes of one direction, the first reading `scene` with offsetFactor 1, the second the
// first's result with offsetFactor 4, each rounded as its target stores it.
std::array<RefImage, 2> streakChain(const RefImage& scene, glm::ivec2 size, glm::dvec2 direction,
                                    TargetRounding rounding);

// The composite at each pixel centre of a width x height screen: min(1, Σ_k (streak_k.rgb ·
// Glow_Factor, 0.15)) with the four streaks sampled bilinearly; with `alpha64` each texel is
// decoded from its alpha first. Not rounded.
RefImage streakCombine(const std::array<RefImage, 4>& streaks, double glowFactor, int width, int height,
                       bool alpha64);

}  // namespace rmfx::test
