#pragma once
// Float64 reference of the bloom and streak stage workspaces of issue 7 (effects/variants/bloom.xml,
// streak.xml): the same discrete algorithms as their shaders, written from the stage contract,
// without any target rounding (what rgba32f intermediates approach). Texel (i, j) covers
// [i, i+1) x [j, j+1), row 0 at the bottom; every tap outside an image reads black.

#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "reference/CpuImage.h"

namespace rmfx::test {

// NaN, ±Inf and negative colour channels as 0 (alpha kept).
RefImage sanitised(const RefImage& input);

// The factor between the input and a target at the reduced size: the smallest of 2, 4, 8 with
// ceil(input / n) == reduced on both axes (variant_target.glsl's reductionFactor).
int reductionFactor(glm::ivec2 inputSize, glm::ivec2 reducedSize);
glm::ivec2 reducedSize(glm::ivec2 size, int n);  // ceil(size / n), at least 1

// B = max(S - threshold, 0) of the sanitised input, box-averaged over blocks of n x n texels (edge
// blocks average the texels they have).
RefImage reducedBright(const RefImage& input, int n, double threshold);

// Bilinear at `position` (texels) with black outside / with clamp-to-edge addressing.
glm::dvec3 bilinearOrBlack(const RefImage& image, glm::dvec2 position);
glm::dvec3 bilinearClamped(const RefImage& image, glm::dvec2 position);

// The bloom stage's blur kinds, in the workspace's effect names.
enum class BloomBlur { Gauss9x1, Gauss9x2, Gauss9x4, Gauss49, Linear9x2, Kawase, DualFilter, Tent13 };
const std::vector<BloomBlur>& allBloomBlurs();
std::string bloomBlurName(BloomBlur blur);

// The parameters the shaders derive from sigma_D (bloom_blur.glsl): Kawase's offset scale s and the
// radius r of the dual-filter / tent13 pyramids (kind 0 / 1), each solving "chain variance per
// axis = sigma_D^2" by the same bisection; and those variances.
double kawaseVariance(double s);
double kawaseScale(double sigma);
double dualFilterVariance(double r);
double tent13Variance(double r);
double pyramidRadius(int kind, double sigma);

// `blurred` at the reduced size from `down` (the reduced bright part) for a blur of sigma_D.
RefImage bloomBlur(BloomBlur blur, const RefImage& down, double sigmaD);

struct BloomSettings {
    double threshold = 1.0;
    double strength = 0.5;
    double sigma = 0.03125;  // of the image height
};

struct StageImages {
    RefImage down;                 // the reduced bright part
    std::vector<RefImage> blurred;  // bloom: one image; streak: the four directions
    RefImage result;               // full size
};

// The whole bloom stage on an input of the workspace's size, reduced by n.
StageImages bloomStage(const RefImage& input, BloomBlur blur, const BloomSettings& settings, int n = 4);

struct StreakSettings {
    double threshold = 1.0;
    double strength = 0.5;
    double length = 0.19;  // e-folding length, of the image height
};

// One streak pass (streak_pass.glsl) along `direction` at the reduced size: pass p takes texels at
// 4^p i steps (i = 0..3) weighted exp(-stepDecay 4^p i), the first also times 1 - exp(-stepDecay).
RefImage streakPass(const RefImage& source, glm::ivec2 direction, int pass, double stepDecay);

// The whole streak stage with P passes per direction; blurred holds the directions (1,1), (-1,1),
// (1,-1), (-1,-1).
StageImages streakStage(const RefImage& input, int passes, const StreakSettings& settings, int n = 4);

// The composite of either stage: S + strength * U, U the bilinear (clamp-to-edge) upsample of
// `reduced` at pixel centre / n.
RefImage stageComposite(const RefImage& input, const RefImage& reduced, int n, double strength);

}  // namespace rmfx::test
