#pragma once
// Reading, writing, resampling and comparing images needs OpenImageIO, which brings about 260
// shared libraries whose dynamic linking costs about half a second of CPU before main() (Debian
// builds them with -z now). So OpenImageIO is not linked into rmfx's programs: the functions that
// use it live in a module, rmfx-image-codecs.so (io/image/codecs/), loaded the first time an image
// is read or written, or earlier, on a thread of its own, by startLoadingImageCodecs(): a program
// that will read images (rmfx render) starts it first thing and parses and validates meanwhile;
// one that will not (rmfx validate, list, --help) never pays for it.
//
// The public functions (ImageIO.h, InputImage.h, ImageCompare.h, DdsCubeMap.h,
// ImageMemoryLimit.h) go through the module's table; callers do not see it. The module is found
// as $RMFX_IMAGE_CODECS, else beside the program or library that holds this code (librmfx.so),
// else in the lib folder of the package installed around that file (core/InstallLayout.h: an
// installed rmfx or Python module), else where this build put it.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "core/Result.h"
#include "io/image/ImageCompare.h"
#include "io/image/ImageIO.h"
#include "io/image/InputImage.h"
#include "model/Image.h"

namespace rmfx {

// What the module exports as kImageCodecsEntry: the build's own types cross the boundary, so a
// module from another build is refused (kImageCodecsVersion and the table's size).
inline constexpr int kImageCodecsVersion = 1;
inline constexpr const char* kImageCodecsEntry = "rmfx_image_codecs_v1";
inline constexpr const char* kImageCodecsFileName = "rmfx-image-codecs.so";

struct ImageCodecs {
    int version = kImageCodecsVersion;
    std::size_t size = sizeof(ImageCodecs);
    Result<Image> (*readImage)(const std::filesystem::path& file);
    Result<Image> (*readVolumeImage)(const std::filesystem::path& file);
    Result<void> (*writeImage)(const std::filesystem::path& file, const Image& image, const WriteOptions& options);
    Result<InputImage> (*readInputImage)(const std::filesystem::path& file, const std::string& layer, int maxSide);
    Result<Image> (*resampleImage)(const Image& image, int width, int height);
    ImageComparison (*compareImages)(const Image& actual, const Image& reference, const CompareLimits& limits);
    Result<void> (*checkImageFileMemory)(const std::filesystem::path& file);
    Result<CubeFaces> (*readDdsCubeMap)(const std::filesystem::path& file);
};

// The module's entry: its table, reading the image memory limit through the host's function.
using ImageCodecsEntry = const ImageCodecs* (*)(std::uint64_t (*hostImageMemoryLimit)());

// Starts loading the module on a thread of its own and returns at once; later calls do nothing.
// `first`: what that thread loads before, a library the caller needs sooner (rmfx render: the GL
// driver, which the loader's lock would otherwise hold back until the codecs are in).
void startLoadingImageCodecs(std::function<void()> first = {});

// The loaded module's table (waiting for a load under way, or loading it now), or why it cannot
// be loaded: the path tried and the loader's reason.
const Result<const ImageCodecs*>& imageCodecs();

}  // namespace rmfx
