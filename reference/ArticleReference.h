#pragma once
// Float64 twin of the GameDev.net article's pipeline (effects/article_pipeline.xml), written from
// the article's definitions: SuppressLDR downsample, the 17-tap binomial blur, the tone map.

#include <glm/vec3.hpp>

#include "reference/CpuImage.h"

namespace rmfx::test::article {

// One bilinear fetch of `scene` at each pixel centre of a width x height target, times Kd, kept
// only where a channel exceeds 1.
RefImage downsampleSuppressLdr(const RefImage& scene, int width, int height, glm::dvec3 kd);

// The binomial weights C(16, 8 + i) / 2^16 for i = -8..8, as exact doubles.
double blurWeight(int offset);

// One blur axis: taps at whole-texel offsets -8..8 along (dx, dy), clamped at the edges.
RefImage blur17(const RefImage& image, int dx, int dy);

// The tone map of the pixel at uv: mix(original, blur, 0.4) · (1 − |uv − ½|²)^4 · exposure,
// then ^0.55 per channel (negatives to 0). `blur` is the bilinear fetch of the blurred target.
glm::dvec3 toneMap(glm::dvec3 original, glm::dvec3 blur, glm::dvec2 uv, double exposure);

}  // namespace rmfx::test::article
