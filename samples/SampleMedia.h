#pragma once
// Media for the sample workspaces, computed rather than shipped: `rmfx_make_media DIR` writes them,
// and tests call these functions directly.

#include <filesystem>

#include <glm/vec3.hpp>

#include "runtime/Image.h"
#include "runtime/Result.h"

namespace rmfx::samples {

// HDR sky radiance for a unit direction: a blue gradient (about 0.1 to 1.5) over a dark ground
// (0.02 .. 0.2) and a sun disc of `sunIntensity` around `sunDirection` (unit length).
glm::vec3 analyticSky(const glm::vec3& direction, const glm::vec3& sunDirection, float sunIntensity);

// A horizontal cross (4N x 3N, float RGB) of analyticSky; the six unused blocks are black.
Image makeSkyCross(int faceSize, const glm::vec3& sunDirection, float sunIntensity);

// An 8-bit single-channel disc: 1 inside radius 0.4 of the image, 0 outside, 2-pixel soft edge.
Image makeDiscMask(int size);

// Writes what samples/tour/tour.xml reads (mask.png, sky_cross.exr) into `folder`.
Result<bool> writeTourMedia(const std::filesystem::path& folder);

}  // namespace rmfx::samples
