#pragma once
// The most memory one decoded image may take, checked from the file's header before any pixel is
// read: a small file whose header claims 16000x16000 is refused at once instead of costing
// seconds and gigabytes first. The limit is the run's (--max-image-memory MiB sets it).

#include <cstdint>
#include <filesystem>

#include "core/Result.h"

namespace rmfx {

// 2 GiB: a 16384x8192 RGBA float panorama, and nothing larger.
inline constexpr std::uint64_t kDefaultImageMemoryLimit = std::uint64_t(2048) << 20;

std::uint64_t imageMemoryLimit();
void setImageMemoryLimit(std::uint64_t bytes);

// The bytes an image takes decoded as rmfx holds it: `channels` floats a pixel.
std::uint64_t decodedImageBytes(std::int64_t width, std::int64_t height, std::int64_t depth, int channels);

// An error naming the file, its size and both figures when the decoded image would take more
// than the limit.
Result<void> checkImageMemory(const std::filesystem::path& file, std::int64_t width, std::int64_t height,
                              std::int64_t depth, int channels);

// The same from the file's header alone, before anything else is loaded: an error only when every
// image the file holds (each part of a multi-part EXR) is over the limit, so that no choice of
// part or layer could be read. A file that cannot be opened is left to the reader to report.
Result<void> checkImageFileMemory(const std::filesystem::path& file);

}  // namespace rmfx
