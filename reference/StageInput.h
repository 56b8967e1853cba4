#pragma once
// The stage workspaces' input as the contract of issue 7 defines it (effects/variants/): each Input
// texel sanitised (NaN, ±Inf and negative channels as 0) and its Rec.709 luminance. Float64, from
// the definitions, for the CPU references of the luminance and tone map stages.

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "reference/CpuImage.h"

namespace rmfx::test {

glm::dvec3 sanitisedTexel(glm::dvec4 texel);
double rec709Luminance(glm::dvec3 rgb);

// The contract's input S: fromImage (row 0 at the bottom; one or two channels are grey, the second
// alpha, as the runtime uploads them) with every texel's rgb sanitised; alpha as it is.
RefImage sanitisedInput(const Image& image);

// A deterministic test image: each pixel's luminance log-uniform in [2^minLog2, 2^maxLog2] (a
// fraction `black` of them exactly 0), its colour a random chroma with that Rec.709 luminance.
// `binWidthLog2` > 0 puts log2(Y) at most 0.3 bin widths from the centre of a bin of that width
// starting at minLog2 (so that float and double agree on every pixel's bin).
RefImage syntheticHdrImage(int width, int height, unsigned seed, double minLog2, double maxLog2, double black = 0.0,
                           double binWidthLog2 = 0.0);

}  // namespace rmfx::test
