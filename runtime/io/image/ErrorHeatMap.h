#pragma once
// An error image (io/image/ImageCompare.h) as a picture of where the error is.

#include "model/Image.h"

namespace rmfx {

// The heat map of an error image: each pixel's largest error over its channels, scaled by
// 1 / `scale` onto the magma colour map, and cyan where it exceeds `scale`. 8-bit RGB values.
Image errorHeatMap(const Image& difference, double scale);

}  // namespace rmfx
