#pragma once
// Float64 references for effects/auto_exposure.xml, from the chapter's definitions: the average
// brightness of the scene (a plain mean over every pixel) and the per-frame exposure update
//   Exposure = lerp(Exposure, 0.5 / Average_Brightness, Exposure_Adjust_Speed).

#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "reference/CpuImage.h"

namespace rmfx::test {

// Rec.709 luminance after NaN and negative channels become 0 and +Inf becomes 65504.
double sanitisedBrightness(glm::dvec3 rgb);

// The exact mean brightness over every pixel of `scene`.
double meanBrightness(const RefImage& scene);

// Level `level` (1 = half size) of the reduction chain: sizes ceil(previous / 2); pixel (x, y)
// covers scene pixels [x·2^level, (x+1)·2^level) clipped to the scene. r = mean brightness of
// those pixels, g = their count.
RefImage brightnessLevel(const RefImage& scene, int level);
// Sizes of levels 1.. until 1x1 is reached (the 1x1 level included).
std::vector<glm::ivec2> chainSizes(glm::ivec2 viewport);

// What a naive half-size chain computes: each level floor(previous / 2) (at least 1), each pixel
// the plain mean of its 2x2 source texels (clamped), so an odd last row or column is dropped.
double naiveChainMean(const RefImage& scene);

// 0.5 / max(average, floor): the exposure the adaptation moves towards.
double targetExposure(double averageBrightness, double floor);
// e_0 = initial, e_{n+1} = e_n + (target − e_n)·speed; returns e_frames.
double exposureAfterFrames(double initial, double target, double speed, int frames);

}  // namespace rmfx::test
