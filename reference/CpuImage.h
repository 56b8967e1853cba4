#pragma once
// Float64 images and GL-style sampling: the one image type of reference/, the float64 CPU
// references that the GL tests compare the shaders with and that `rmfx bench` measures the variants
// against (Ideal*.h). The effects' maths is re-implemented on these from the chapter's definitions,
// independently of the shaders.

#include <functional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "model/Image.h"

namespace rmfx::test {

// Row 0 is the BOTTOM row, as in a GL texture: uv (0, 0) is the bottom-left corner. Every RefImage
// has this row order; fromImage flips a runtime Image (row 0 at the top) into it.
struct RefImage {
    int width = 0;
    int height = 0;
    std::vector<glm::dvec4> texels;

    RefImage() = default;
    RefImage(int w, int h, glm::dvec4 fill = glm::dvec4(0.0)) : width(w), height(h), texels(size_t(w) * h, fill) {}
    glm::dvec4& at(int x, int y) { return texels[size_t(y) * width + x]; }
    const glm::dvec4& at(int x, int y) const { return texels[size_t(y) * width + x]; }
};

// From an image read back with readTarget / readImage (row 0 at the top), rows flipped. One or two
// channels: the first fills rgb, the second is alpha (as the runtime uploads them); a missing
// alpha is 1.
RefImage fromImage(const Image& image);

// Largest |gl - ref| - (relative · |ref| + absolute) over rgb: <= 0 passes. +Inf when the sizes
// differ or a difference is NaN.
double worstExcess(const RefImage& gl, const RefImage& ref, double relative, double absolute);

// Texel fetch with clamp-to-edge addressing.
glm::dvec4 fetchClamped(const RefImage& image, int x, int y);

// The four texels GL_LINEAR with GL_CLAMP_TO_EDGE blends at uv, and the fractions it blends them by.
struct BilinearFootprint {
    glm::dvec4 texels[4];  // (i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1)
    double fx, fy;
};
BilinearFootprint bilinearFootprint(const RefImage& image, glm::dvec2 uv);

// GL_LINEAR / GL_NEAREST lookups with GL_CLAMP_TO_EDGE, texel centres at (i + 0.5) / size.
glm::dvec4 sampleBilinear(const RefImage& image, glm::dvec2 uv);
glm::dvec4 sampleNearest(const RefImage& image, glm::dvec2 uv);
// Per channel, max − min of the four texels sampleBilinear blends at uv (0 where the footprint is
// flat and any filtering returns the texel exactly).
glm::dvec4 bilinearFootprintRange(const RefImage& image, glm::dvec2 uv);

// Evaluates `shade(uv)` at every pixel centre of a width x height target, as a full-screen pass does.
RefImage shadePixels(int width, int height, const std::function<glm::dvec4(glm::dvec2 uv)>& shade);

// What a render target of that format stores for a value: IEEE half with round-to-nearest-even
// (overflow to ±Inf), or 8-bit unorm (clamped to [0, 1], rounded to k / 255).
double roundToHalf(double value);
double roundToUnorm8(double value);
RefImage roundedToHalf(const RefImage& image);
RefImage roundedToUnorm8(const RefImage& image);

// What a render target of that format keeps of every value.
enum class TargetRounding { Half, Unorm8 };
RefImage roundedTo(const RefImage& image, TargetRounding rounding);

// The chapter's 8-bit intensity encoding (shader_6, exercise 2): colour in rgb (0..1), the HDR
// multiplier / 64 in alpha, decoded as rgb · (a · 64). decodedAlpha64 decodes every texel, alpha 1
// (the copy of such a scene to the screen).
glm::dvec4 encodeAlpha64(glm::dvec3 rgb, double multiplier);
glm::dvec3 decodeAlpha64(glm::dvec4 encoded);
RefImage decodedAlpha64(const RefImage& image);

// dst.rgb + src.rgb · src.a with dst's alpha kept, what the effects' additive combines write:
// <blend mode="custom" src="src-alpha" dst="one" src-alpha="zero" dst-alpha="one"/> (sizes must
// match). Not rounded.
RefImage blendedAdditive(const RefImage& dst, const RefImage& src);

// The largest r, g or b of any texel.
double maxColorChannel(const RefImage& image);

// Largest per-channel |a − b| over the first `channels` channels (sizes must match, else +Inf).
double maxAbsDifference(const RefImage& a, const RefImage& b, int channels = 4);
// Largest per-channel |a − b| / max(|b|, floor).
double maxRelativeDifference(const RefImage& a, const RefImage& b, double floor, int channels = 4);
// Largest per-channel |a − b| / (relative · max(|b|, floor) + allowance[c]) over the first `channels`
// channels, allowance an image of b's size: at most 1 when every texel is within its bound.
double maxDifferenceOverBound(const RefImage& a, const RefImage& b, double relative, double floor, const RefImage& allowance,
                              int channels = 4);

}  // namespace rmfx::test
