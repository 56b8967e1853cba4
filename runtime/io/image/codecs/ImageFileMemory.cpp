#include <algorithm>
#include <filesystem>
#include <system_error>

#include <OpenImageIO/imageio.h>

#include "io/image/ImageMemoryLimit.h"
#include "io/image/codecs/CodecFunctions.h"

namespace rmfx::codecs {

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

}  // namespace rmfx::codecs
