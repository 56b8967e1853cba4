// writeImage (declared in ImageIO.h): format by extension, display transform and quantisation.
#include "io/image/codecs/CodecFunctions.h"
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "io/file/AtomicFile.h"
#include "io/file/OutputPath.h"
#include "io/image/ImageOutputPath.h"
#include "io/image/ImageFileError.h"
#include "io/image/ImageIO.h"

namespace rmfx::codecs {

namespace fs = std::filesystem;

namespace {

struct Target {
    ImageContainer container;
    bool integer;
};

std::optional<Target> targetFor(const fs::path& file) {
    const std::optional<ImageContainer> container = imageContainerFor(file);
    if (!container) return std::nullopt;
    return Target{*container, *container != ImageContainer::Exr && *container != ImageContainer::Rgbe};
}

bool hasAlpha(int channels) { return channels == 2 || channels == 4; }

// Channel counts a container cannot store are adapted: Radiance files hold RGB only (grey is
// replicated, alpha dropped); JPEG drops alpha, and so do the other integer formats when asked to.
int storedChannels(const Target& target, int channels, bool integerOpaque) {
    if (target.container == ImageContainer::Rgbe) return 3;
    if ((target.container == ImageContainer::Jpeg || (target.integer && integerOpaque)) && hasAlpha(channels)) return channels - 1;
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

Result<void> writeImage(const fs::path& file, const Image& image, const WriteOptions& options) {
    const std::optional<Target> target = targetFor(file);
    if (!target)
        return Error{checkImageOutputPath(file).error()};
    if (image.width <= 0 || image.height <= 0 || image.channels < 1 || image.channels > 4 ||
        image.pixels.size() != size_t(image.width) * image.height * image.channels)
        return imageFileError(file, "cannot write an empty or inconsistent image (" +
                                   std::to_string(image.width) + "x" + std::to_string(image.height) +
                                   ", " + std::to_string(image.channels) + " channels, " +
                                   std::to_string(image.pixels.size()) + " values)");
    if (options.pngBits != 8 && options.pngBits != 16)
        return imageFileError(file, "PNG bits per channel must be 8 or 16, not " + std::to_string(options.pngBits));
    if (Result<void> usable = checkOutputFile(file); !usable) return Error{usable.error()};

    const int stored = storedChannels(*target, image.channels, options.integerOpaque);
    const std::vector<int> map = channelMap(image.channels, stored);
    const bool sixteen = target->container == ImageContainer::Png && options.pngBits == 16;

    OIIO::TypeDesc format = OIIO::TypeDesc::FLOAT;
    if (target->integer)
        format = sixteen ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8;
    else if (target->container == ImageContainer::Exr && options.exrHalf)
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
    if (target->container == ImageContainer::Jpeg)
        spec.attribute("CompressionQuality", 95);

    // Encoded in memory, then put in place whole by one rename: a full disk, a file-size limit
    // or a crash leaves the previous file as it was, never a part of the new one.
    auto out = OIIO::ImageOutput::create(file.string());
    if (!out)
        return imageFileError(file, "no writer: " + oneLine(OIIO::geterror()));
    std::vector<unsigned char> encoded;
    OIIO::Filesystem::IOVecOutput memory(encoded);
    void* proxy = &memory;
    spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    if (!out->open(file.string(), spec))
        return imageFileError(file, "cannot encode: " + oneLine(out->geterror()));

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
        return imageFileError(file, "cannot encode the pixels: " + oneLine(out->geterror()));
    if (!out->close())
        return imageFileError(file, "cannot finish encoding: " + oneLine(out->geterror()));
    const std::string_view bytes(reinterpret_cast<const char*>(encoded.data()), encoded.size());
    if (Result<void> written = writeFileAtomically(file, bytes, false); !written) return Error{written.error()};
    return {};
}

}  // namespace rmfx::codecs
