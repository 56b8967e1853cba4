#include "io/image/ImageOutputPath.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "io/file/OutputPath.h"
#include "io/image/ImageFileError.h"

namespace rmfx {

std::optional<ImageContainer> imageContainerFor(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".exr") return ImageContainer::Exr;
    if (ext == ".hdr") return ImageContainer::Rgbe;
    if (ext == ".png") return ImageContainer::Png;
    if (ext == ".jpg" || ext == ".jpeg") return ImageContainer::Jpeg;
    if (ext == ".tga") return ImageContainer::Tga;
    if (ext == ".bmp") return ImageContainer::Bmp;
    return std::nullopt;
}

const char* knownImageOutputExtensions() { return ".exr .hdr .png .jpg .jpeg .tga .bmp"; }

Result<void> checkImageOutputPath(const std::filesystem::path& file) {
    if (!imageContainerFor(file))
        return imageFileError(file, (file.extension().empty() ? std::string("no image file extension")
                                                              : "unknown image file extension '" + file.extension().string() + "'") +
                                        " (known: " + knownImageOutputExtensions() + ")");
    return checkOutputFile(file);
}

}  // namespace rmfx
