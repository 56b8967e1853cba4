#pragma once
// Reading and writing image files through OpenImageIO.
//
// Reads give float pixels exactly as the file holds them: integer data as value / max (8-bit:
// byte / 255), float and half data unchanged. No colour conversion and no alpha premultiplication
// happens on the way in.

#include <filesystem>

#include "core/Result.h"
#include "model/Image.h"

namespace rmfx {

// Any format OpenImageIO reads. Keeps 1..4 channels (files with more keep the first four).
// Errors name the file.
Result<Image> readImage(const std::filesystem::path& file);
// A volume (3D) image, such as a DDS volume texture: Image::depth slices. A 2D file is an error.
Result<Image> readVolumeImage(const std::filesystem::path& file);

struct WriteOptions {
    DisplayTransform transform = DisplayTransform::None;
    bool exrHalf = false;  // .exr: 16-bit half instead of 32-bit float
    int pngBits = 8;       // .png: 8 or 16
    bool integerOpaque = false;  // integer formats store colour only (alpha dropped); .exr, .hdr as usual
};

// The format comes from the extension: .exr and .hdr keep linear float data and ignore the
// display transform; .png, .jpg/.jpeg, .tga, .bmp are integer formats: colour channels get the
// transform (alpha never does), then each value is clamped to [0, 1] (NaN to 0) and rounded to
// the nearest step. Errors name the file.
Result<void> writeImage(const std::filesystem::path& file, const Image& image, const WriteOptions& options);
Result<void> writeImage(const std::filesystem::path& file, const Image& image,
                        DisplayTransform transform = DisplayTransform::None);

// The sRGB transfer functions, piecewise (linear segment below 0.0031308 / 0.04045).
// Defined for any input: negatives follow the linear segment, NaN stays NaN.
float srgbEncode(float linear);
float srgbDecode(float encoded);

}  // namespace rmfx
