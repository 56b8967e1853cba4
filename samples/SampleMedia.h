#pragma once
// Media for the sample workspaces, computed rather than shipped: `rmfx_make_media DIR` writes them,
// and tests call these functions directly.

#include <filesystem>

#include <glm/vec3.hpp>

#include "core/Result.h"
#include "model/Image.h"

namespace rmfx::samples {

// HDR sky radiance for a unit direction: a blue gradient (about 0.1 to 1.5) over a dark ground
// (0.02 .. 0.2) and a sun disc of `sunIntensity` around `sunDirection` (unit length).
glm::vec3 analyticSky(const glm::vec3& direction, const glm::vec3& sunDirection, float sunIntensity);

// A horizontal cross (4N x 3N, float RGB) of analyticSky; the six unused blocks are black. Each
// texel averages samplesPerAxis² point samples, so the sun disc's edge is antialiased rather than
// a staircase of texels.
Image makeSkyCross(int faceSize, const glm::vec3& sunDirection, float sunIntensity, int samplesPerAxis = 1);

// An 8-bit single-channel disc: 1 inside radius 0.4 of the image, 0 outside, 2-pixel soft edge.
Image makeDiscMask(int size);

// Writes what samples/tour/tour.xml reads (mask.png, sky_cross.exr) into `folder`.
Result<void> writeTourMedia(const std::filesystem::path& folder);

// The chapter's 8-bit HDR encoding: colour in rgb, brightness in alpha, decoded as
// rgb * (1 + 64 a): HdrEncoding::Rgba8x64 (runtime/HdrEncoding.h) on every texel. Each texel gets
// the smallest 8-bit alpha whose multiplier reaches its largest channel, so rgb keeps as many of
// its 8 bits as possible; values above 65 are scaled down to 65 keeping their hue. Returns an RGBA
// image with 8-bit values (k / 255).
Image encodeAlphaIntensity(const Image& hdr);
glm::vec3 decodeAlphaIntensity(float r, float g, float b, float a);

// The lens-flare mask of the chapter (its figure 8.9): white, with alpha 1 inside radius 0.3 of the
// image falling smoothly to 0 at radius 0.5, so scaled ghost images lose their hard borders.
Image makeGhostMask(int size);

// The chapter scene's sun: low above the horizon, in view of the effects' default camera.
inline const glm::vec3 kChapterSunDirection{-0.35f, 0.12f, -0.93f};
inline constexpr float kChapterSunIntensity = 2000.0f;

// A flat HDR test image for the stage workspaces of effects/variants/ (float RGB, width x height):
// a dim floor (0.002 .. 0.05) under a sky gradient (0.3 .. 2), a window of 20, a lamp disc of 200,
// a 3x3 light of 5000, a one-texel light of 60000 and a thin line of 50, so every stage sees dark
// detail, bright areas, highlights near the fp16 limit and single-texel fireflies.
Image makeHdrTestScene(int width, int height);

// Writes the media of the chapter-8 workspaces in effects/ into `folder`: sky_cross.exr (half
// float, 256-texel faces, range 0.02 .. 2000), sky_cross_alpha64.png (the same sky in the
// chapter's alpha encoding), ghost_mask.png and hdr_scene.exr (makeHdrTestScene, 512x512, float).
Result<void> writeChapterMedia(const std::filesystem::path& folder);

}  // namespace rmfx::samples
