#include <string>

#include "io/image/ImageFileError.h"
#include "io/image/ImageMemoryLimit.h"

namespace rmfx {
namespace {

std::string mebibytes(std::uint64_t bytes) { return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB"; }

}  // namespace

std::uint64_t decodedImageBytes(std::int64_t width, std::int64_t height, std::int64_t depth, int channels) {
    return std::uint64_t(width) * std::uint64_t(height) * std::uint64_t(depth) * std::uint64_t(channels) * sizeof(float);
}

Result<void> checkImageMemory(const std::filesystem::path& file, std::int64_t width, std::int64_t height,
                              std::int64_t depth, int channels) {
    const std::uint64_t bytes = decodedImageBytes(width, height, depth, channels);
    if (bytes <= imageMemoryLimit()) return {};
    std::string size = std::to_string(width) + "x" + std::to_string(height) + (depth > 1 ? "x" + std::to_string(depth) : "");
    return imageFileError(file, "image is " + size + ": decoded it would take " + mebibytes(bytes) +
                                    ", over the limit of " + mebibytes(imageMemoryLimit()) +
                                    " (--max-image-memory MiB raises it)");
}

}  // namespace rmfx
