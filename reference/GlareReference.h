#pragma once
// Float64 reference of the chapter-8 glare family (shader_2, shader_6, exercise 1), written from
// the chapter's definitions: the 9- and 49-sample Gauss passes, the chain of passes with the
// rounding of the targets they write, and the composite (target rounding, the 8-bit alpha x64
// intensity encoding and the additive blend are in CpuImage.h).

#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "reference/CpuImage.h"

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

// One full-screen blur pass into a width x height target: at each pixel centre uv, the sum of
// weight · bilinear(source, uv + offset / (width, height)) with clamp-to-edge addressing. Not
// rounded.
RefImage blurPass(const RefImage& source, int width, int height, const std::vector<KernelTap>& kernel);

// `passes` blur passes, the first reading `scene`, each writing a target of size `size` and
// rounded as that target stores it. Returns every level (level i at index i − 1).
std::vector<RefImage> blurChain(const RefImage& scene, glm::ivec2 size, const std::vector<KernelTap>& kernel,
                                int passes, TargetRounding rounding);

// What a context's bilinear filtering may add to each level of blurChain(scene, size, kernel, …)
// (`levels`), per texel and channel, as an absolute bound: every tap's weights may be off by
// `weightError` on each axis (tests/support/GlTestSupport.h: bilinearWeightError, about 1e-7 on
// llvmpipe, up to 2^-9 with 8 bits of subtexel precision), which moves the tap by up to twice that
// times the range of its footprint; the kernel's weights (non-negative, summing to 1) carry on
// the bound of the level it reads.
std::vector<RefImage> blurChainFilteringBounds(const RefImage& scene, const std::vector<RefImage>& levels, glm::ivec2 size,
                                               const std::vector<KernelTap>& kernel, double weightError);

// The composite at each pixel of a width x height screen: (Σ Glow_Factor_i · level_i.rgb, 1), the
// levels sampled bilinearly; with `alpha64` each level is decoded from its alpha first. Not rounded.
RefImage glareCombine(const RefImage& level0, const RefImage& level1, const RefImage& level2,
                      glm::dvec3 glowFactors, int width, int height, bool alpha64);

// The same for glareCombine of three levels whose own bounds are `bounds` (not alpha64).
RefImage glareCombineFilteringBound(const RefImage& level0, const RefImage& level1, const RefImage& level2,
                                    const RefImage& bound0, const RefImage& bound1, const RefImage& bound2,
                                    glm::dvec3 glowFactors, int width, int height, double weightError);

// Centroid and per-axis variance (texel²) of one channel taken as a distribution.
struct ImageMoments {
    double total = 0.0;
    glm::dvec2 mean{0.0};
    glm::dvec2 variance{0.0};
};
ImageMoments imageMoments(const RefImage& image, int channel);

}  // namespace rmfx::test
