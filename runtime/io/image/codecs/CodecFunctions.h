#pragma once
// The module's implementations of the public image functions (io/image/ImageCodecs.h), in their
// own namespace so that the module's calls between them stay inside it.

#include <cstdint>
#include <filesystem>
#include <string>

#include "core/Result.h"
#include "io/image/ImageCompare.h"
#include "io/image/ImageIO.h"
#include "io/image/InputImage.h"
#include "model/Image.h"

namespace rmfx::codecs {

Result<Image> readImage(const std::filesystem::path& file);
Result<Image> readVolumeImage(const std::filesystem::path& file);
Result<void> writeImage(const std::filesystem::path& file, const Image& image, const WriteOptions& options);
Result<InputImage> readInputImage(const std::filesystem::path& file, const std::string& layer, int maxSide);
Result<Image> resampleImage(const Image& image, int width, int height);
ImageComparison compareImages(const Image& actual, const Image& reference, const CompareLimits& limits);
Result<void> checkImageFileMemory(const std::filesystem::path& file);
Result<CubeFaces> readDdsCubeMap(const std::filesystem::path& file);

// The host's limit (io/image/ImageMemoryLimit.h), read by the module's checks.
void useHostImageMemoryLimit(std::uint64_t (*hostImageMemoryLimit)());

}  // namespace rmfx::codecs
