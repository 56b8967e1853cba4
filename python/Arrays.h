#pragma once
// Images between NumPy and the runtime. Both ways row 0 is the top of the image, as image files
// and NumPy's image libraries have it (model/Image.h).

#include <optional>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "gl/GlExecutor.h"
#include "model/Image.h"
#include "model/Workspace.h"

namespace rmfx::python {

// An input array as the runtime's linear RGBA float image. Shape (height, width, 3 or 4) of
// float32 or float16 (linear, taken as they are: what a float EXR holds) or uint8 (sRGB-encoded
// colour, decoded to linear as rmfx render decodes an 8-bit PNG; alpha is value / 255). Three
// channels get alpha 1. Any other dtype or shape raises rmfx.Error naming `what`.
Image imageFromArray(const pybind11::handle& array, const std::string& what);

// An input array the GPU can take as it is (GlExecutor::writeInputPixels): shape (height, width,
// 4) of float32 or float16 in native byte order, each pixel's four values packed (rows may be
// apart); none for any other array, which imageFromArray converts (or refuses).
std::optional<GlExecutor::InputPixels> directPixels(const pybind11::handle& array);

// A float32 array of shape (height, width, channels): a copy of the image's pixels.
pybind11::array_t<float> arrayFromImage(const Image& image);
// The same, the array taking the pixels over (no copy).
pybind11::array_t<float> arrayFromImage(Image&& image);

// A target read back (float, exact in its format) in the type the format stores: uint8 (8-bit
// unsigned normalised), uint16 (16-bit), float16 (half floats); float32 for the rest.
pybind11::array targetArray(const Image& image, TargetFormat format);

}  // namespace rmfx::python
