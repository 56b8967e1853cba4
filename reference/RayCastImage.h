#pragma once
// A model effect's expected image from a MeshRayCast: the effect's shading evaluated in double on
// the surface under each pixel centre (as a range, where an input such as a filtered 8-bit texel
// may legitimately come back rounded), the background where there is none, and which pixels a
// comparison with a rasteriser's image may use.

#include <functional>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "reference/CpuImage.h"
#include "reference/MeshRayCast.h"

namespace rmfx::test {

// What a pixel may hold: every channel within [lower, upper].
struct ExpectedRange {
    glm::dvec4 lower, upper;
    ExpectedRange() = default;
    explicit ExpectedRange(glm::dvec4 exact) : lower(exact), upper(exact) {}
    ExpectedRange(glm::dvec4 lo, glm::dvec4 hi) : lower(lo), upper(hi) {}
};

using SurfaceShading = std::function<ExpectedRange(const SurfaceHit&)>;
// Whether the surface at pixel (i, j) (j from the bottom) takes part in the comparison: false
// where the reference does not model what the GPU does (e.g. a coarse mipmap level).
using SurfaceFilter = std::function<bool(const SurfaceHit&, int i, int j)>;

struct RayCastImage {
    RefImage lower, upper;       // row 0 at the bottom
    std::vector<char> compared;  // per pixel: settled (MeshRayCast::settled) and not filtered out
    int surfacePixels = 0;       // pixel centres on the surface
    int comparedSurfacePixels = 0;
};

RayCastImage rayCastImage(const MeshRayCast& cast, const SurfaceShading& shade, glm::dvec4 background,
                          const SurfaceFilter& comparable = {});

// The largest distance of a compared pixel's channel (the first `channels`) outside its range
// (+Inf when the sizes differ or a value is NaN), and where it is.
struct RayCastDifference {
    double worst = 0.0;
    int x = -1, y = -1, channel = -1;  // y from the bottom
    std::string describe(const RefImage& image, const RayCastImage& reference) const;
};
RayCastDifference worstExcess(const RefImage& image, const RayCastImage& reference, int channels = 4);

}  // namespace rmfx::test
