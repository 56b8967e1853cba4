#pragma once
// A texture's mipmap levels made on the CPU, the same on every driver: each level is the one
// above reduced by an area (box) filter, each texel the average of the texels of the level above
// that its footprint covers, weighted by how much of each it covers (a 2x2 average where a size
// halves exactly; odd sizes weigh the edge texels they split). Sizes follow OpenGL's
// (max(1, size >> level) on each axis). sRGB-encoded data is averaged as linear light and encoded
// again; alpha is always averaged as it is.

#include <vector>

#include "model/Image.h"

namespace rmfx {

enum class MipEncoding { Linear, Srgb };

// Levels 1 … levels-1 below `base` (a 2D image or a volume of base.depth slices; volumes reduce
// their depth too). Each level keeps base's channels and flags.
std::vector<Image> mipLevelsBelow(const Image& base, int levels, MipEncoding encoding);

}  // namespace rmfx
