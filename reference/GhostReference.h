#pragma once
// Float64 reference of the chapter-8 ghosts (shader_4), written from the chapter's definitions:
// the source sampled at four copies of the texture coordinates scaled about the centre, each
// masked, two passes with the rounding of the targets they write, and the composite.

#include <array>
#include <vector>

#include <glm/vec2.hpp>

#include "reference/CpuImage.h"

namespace rmfx::test {

// The chapter's scales, in the order of its vertex shader's texCoord1..4.
inline constexpr std::array<double, 4> kGhostScales{-2.0, 2.0, -0.6, 0.6};

// One ghost pass into a width x height target: at each pixel centre uv, Glow_Factor · Σ_s
// bilinear(source, c_s) · bilinear(mask, c_s).a with c_s = (uv − 0.5) · s + 0.5, clamp-to-edge
// addressing for both. Not rounded.
RefImage ghostPass(const RefImage& source, const RefImage& mask, int width, int height, double glowFactor);

// The two passes, the first reading `scene`, the second the first's result, each rounded as its
// target stores it.
std::array<RefImage, 2> ghostChain(const RefImage& scene, const RefImage& mask, glm::ivec2 size, double glowFactor,
                                   TargetRounding rounding);

// The composite at each pixel centre of a width x height screen: (bilinear(ghosts, uv).rgb, 0.8).
RefImage ghostComposite(const RefImage& ghosts, int width, int height);

// Where a pass draws the ghosts of a point `light` of its source (texture coordinates): the pixel
// whose scaled coordinate c_s lands on the light, 0.5 + (light − 0.5) / s, for each scale; after
// `passes` passes, for every product of `passes` scales (duplicates kept).
std::vector<glm::dvec2> ghostPositions(glm::dvec2 light, int passes);

}  // namespace rmfx::test
