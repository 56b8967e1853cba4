#pragma once
// Float64 reference of the chapter-8 glare family (shader_2, shader_6, exercise 1), written from
// the chapter's definitions: the 9- and 49-sample Gauss passes, the chain of passes with the
// rounding of the targets they write, the composite, and the 8-bit alpha x64 intensity encoding.

#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "tests/reference/CpuImage.h"

namespace rmfx::test {

struct KernelTap {
    glm::dvec2 offset;  // in texels of the target being rendered
    double weight;
};

// The chapter's 9-sample Gauss table with its repeated (-1, 1) row replaced by (-1, -1): the 3x3
// binomial (1 2 1)/4 x (1 2 1)/4.
std::vector<KernelTap> gauss9Kernel();
// The 49-sample Gauss filter: the 7x7 binomial, the outer product of (1 6 15 20 15 6 1)/64.
std::vector<KernelTap> gauss49Kernel();

// Per-axis variance of a kernel (texel²): 0.5 for gauss9, 1.5 for gauss49.
glm::dvec2 kernelVariance(const std::vector<KernelTap>& kernel);

// What a target of that format keeps of a value.
enum class TargetRounding { Half, Unorm8 };
RefImage roundedTo(const RefImage& image, TargetRounding rounding);

// One full-screen blur pass into a width x height target: at each pixel centre uv, the sum of
// weight · bilinear(source, uv + offset / (width, height)) with clamp-to-edge addressing. Not
// rounded.
RefImage blurPass(const RefImage& source, int width, int height, const std::vector<KernelTap>& kernel);

// `passes` blur passes, the first reading `scene`, each writing a target of size `size` and
// rounded as that target stores it. Returns every level (level i at index i − 1).
std::vector<RefImage> blurChain(const RefImage& scene, glm::ivec2 size, const std::vector<KernelTap>& kernel,
                                int passes, TargetRounding rounding);

// The composite at each pixel of a width x height screen: (Σ Glow_Factor_i · level_i.rgb, 1), the
// levels sampled bilinearly; with `alpha64` each level is decoded from its alpha first. Not rounded.
RefImage glareCombine(const RefImage& level0, const RefImage& level1, const RefImage& level2,
                      glm::dvec3 glowFactors, int width, int height, bool alpha64);

// The chapter's 8-bit intensity encoding of a colour (rgb in 0..1) and its HDR multiplier:
// (rgb, multiplier / 64); decoded as rgb · (a · 64).
glm::dvec4 encodeAlpha64(glm::dvec3 rgb, double multiplier);
glm::dvec3 decodeAlpha64(glm::dvec4 encoded);
// Every texel decoded, alpha 1 (the shader_6 copy of the scene to the screen).
RefImage decodedAlpha64(const RefImage& image);

// dst + src · src.a, what <blend mode="custom" src="src-alpha" dst="one"/> writes. Not rounded.
RefImage blendedAdditive(const RefImage& dst, const RefImage& src);

// Centroid and per-axis variance (texel²) of one channel taken as a distribution.
struct ImageMoments {
    double total = 0.0;
    glm::dvec2 mean{0.0};
    glm::dvec2 variance{0.0};
};
ImageMoments imageMoments(const RefImage& image, int channel);

}  // namespace rmfx::test
