#include "io/image/ImageMemoryLimit.h"

#include <algorithm>
#include <atomic>
#include <string>

#include <OpenImageIO/imageio.h>

#include "io/image/ImageFileError.h"

namespace rmfx {
namespace {

// Read by the sequence's reading thread while the main one renders.
std::atomic<std::uint64_t> limit{kDefaultImageMemoryLimit};

std::string mebibytes(std::uint64_t bytes) { return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB"; }

}  // namespace

std::uint64_t imageMemoryLimit() { return limit.load(); }

void setImageMemoryLimit(std::uint64_t bytes) { limit.store(bytes); }

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

Result<void> checkImageFileMemory(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) return {};
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) {
        (void)OIIO::geterror();  // the reader says what is wrong with it
        return {};
    }
    Result<void> smallest;
    for (int part = 0; in->seek_subimage(part, 0); ++part) {
        const OIIO::ImageSpec& spec = in->spec();
        Result<void> fits = checkImageMemory(file, std::max(spec.width, spec.full_width), std::max(spec.height, spec.full_height),
                                             std::max(spec.depth, 1), 4);
        if (fits) return {};
        if (part == 0) smallest = fits;
    }
    (void)in->geterror();  // seeking past the last part leaves an error that says nothing about the file
    return smallest;
}

}  // namespace rmfx
