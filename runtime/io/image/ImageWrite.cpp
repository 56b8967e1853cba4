// writeImage (declared in ImageIO.h): format by extension, display transform and quantisation.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "io/image/ImageFileError.h"
#include "io/image/ImageIO.h"

namespace rmfx {

namespace fs = std::filesystem;

namespace {

enum class Container { Exr, Rgbe, Png, Jpeg, Tga, Bmp };

struct Target {
    Container container;
    bool integer;
};

std::optional<Target> targetFor(const fs::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".exr") return Target{Container::Exr, false};
    if (ext == ".hdr") return Target{Container::Rgbe, false};
    if (ext == ".png") return Target{Container::Png, true};
    if (ext == ".jpg" || ext == ".jpeg") return Target{Container::Jpeg, true};
    if (ext == ".tga") return Target{Container::Tga, true};
    if (ext == ".bmp") return Target{Container::Bmp, true};
    return std::nullopt;
}

bool hasAlpha(int channels) { return channels == 2 || channels == 4; }

// Channel counts a container cannot store are adapted: Radiance files hold RGB only (grey is
// replicated, alpha dropped); JPEG drops alpha, and so do the other integer formats when asked to.
int storedChannels(const Target& target, int channels, bool integerOpaque) {
    if (target.container == Container::Rgbe) return 3;
    if ((target.container == Container::Jpeg || (target.integer && integerOpaque)) && hasAlpha(channels)) return channels - 1;
    return channels;
}

// Source channel for each stored channel: identity, dropping alpha, or grey replicated to RGB.
std::vector<int> channelMap(int sourceChannels, int storedCount) {
    std::vector<int> map(storedCount);
    for (int c = 0; c < storedCount; ++c)
        map[c] = (storedCount != sourceChannels && sourceChannels <= 2) ? 0 : c;
    return map;
}

template <class Int>
std::vector<Int> quantise(const Image& image, const std::vector<int>& map, DisplayTransform transform) {
    const double max = static_cast<double>(std::numeric_limits<Int>::max());
    const int alpha = hasAlpha(image.channels) ? image.channels - 1 : -1;
    const size_t pixelCount = size_t(image.width) * image.height;
    std::vector<Int> out(pixelCount * map.size());
    for (size_t p = 0; p < pixelCount; ++p) {
        for (size_t c = 0; c < map.size(); ++c) {
            float v = image.pixels[p * image.channels + map[c]];
            v = std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f);
            if (transform == DisplayTransform::Srgb && map[c] != alpha)
                v = std::clamp(srgbEncode(v), 0.0f, 1.0f);
            out[p * map.size() + c] = static_cast<Int>(std::lround(v * max));
        }
    }
    return out;
}

std::vector<float> selectChannels(const Image& image, const std::vector<int>& map) {
    const size_t pixelCount = size_t(image.width) * image.height;
    std::vector<float> out(pixelCount * map.size());
    for (size_t p = 0; p < pixelCount; ++p)
        for (size_t c = 0; c < map.size(); ++c)
            out[p * map.size() + c] = image.pixels[p * image.channels + map[c]];
    return out;
}

}  // namespace

Result<void> writeImage(const fs::path& file, const Image& image, DisplayTransform transform) {
    WriteOptions options;
    options.transform = transform;
    return writeImage(file, image, options);
}

Result<void> writeImage(const fs::path& file, const Image& image, const WriteOptions& options) {
    const std::optional<Target> target = targetFor(file);
    if (!target)
        return imageFileError(file, "unknown image file extension '" + file.extension().string() +
                                   "' (known: .exr .hdr .png .jpg .jpeg .tga .bmp)");
    if (image.width <= 0 || image.height <= 0 || image.channels < 1 || image.channels > 4 ||
        image.pixels.size() != size_t(image.width) * image.height * image.channels)
        return imageFileError(file, "cannot write an empty or inconsistent image (" +
                                   std::to_string(image.width) + "x" + std::to_string(image.height) +
                                   ", " + std::to_string(image.channels) + " channels, " +
                                   std::to_string(image.pixels.size()) + " values)");
    if (options.pngBits != 8 && options.pngBits != 16)
        return imageFileError(file, "PNG bits per channel must be 8 or 16, not " + std::to_string(options.pngBits));
    const fs::path folder = file.parent_path();
    std::error_code ec;
    if (!folder.empty() && !fs::is_directory(folder, ec))
        return imageFileError(file, "folder '" + folder.string() + "' does not exist");

    const int stored = storedChannels(*target, image.channels, options.integerOpaque);
    const std::vector<int> map = channelMap(image.channels, stored);
    const bool sixteen = target->container == Container::Png && options.pngBits == 16;

    OIIO::TypeDesc format = OIIO::TypeDesc::FLOAT;
    if (target->integer)
        format = sixteen ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8;
    else if (target->container == Container::Exr && options.exrHalf)
        format = OIIO::TypeDesc::HALF;
    OIIO::ImageSpec spec(image.width, image.height, stored, format);
    if (hasAlpha(stored)) {
        spec.alpha_channel = stored - 1;
        // Otherwise OpenImageIO takes colour as premultiplied and divides it by alpha on write.
        spec.attribute("oiio:UnassociatedAlpha", 1);
    }
    if (target->integer && options.transform == DisplayTransform::Srgb)
        spec.attribute("oiio:ColorSpace", "sRGB");
    else if (!target->integer)
        spec.attribute("oiio:ColorSpace", "Linear");
    if (target->container == Container::Jpeg)
        spec.attribute("CompressionQuality", 95);

    auto out = OIIO::ImageOutput::create(file.string());
    if (!out)
        return imageFileError(file, "no writer: " + oneLine(OIIO::geterror()));
    if (!out->open(file.string(), spec))
        return imageFileError(file, "cannot open for writing: " + oneLine(out->geterror()));

    bool ok = false;
    if (!target->integer) {
        const std::vector<float> data = selectChannels(image, map);
        ok = out->write_image(OIIO::TypeDesc::FLOAT, data.data());
    } else if (sixteen) {
        const auto data = quantise<uint16_t>(image, map, options.transform);
        ok = out->write_image(OIIO::TypeDesc::UINT16, data.data());
    } else {
        const auto data = quantise<uint8_t>(image, map, options.transform);
        ok = out->write_image(OIIO::TypeDesc::UINT8, data.data());
    }
    if (!ok)
        return imageFileError(file, "cannot write pixels: " + oneLine(out->geterror()));
    if (!out->close())
        return imageFileError(file, "cannot finish writing: " + oneLine(out->geterror()));
    return {};
}

}  // namespace rmfx
