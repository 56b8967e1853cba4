#include "io/image/ImageIO.h"
#include "io/image/codecs/CodecFunctions.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "io/image/DdsBlockVolume.h"
#include "io/image/ImageFileError.h"
#include "io/image/ImageMemoryLimit.h"

namespace rmfx::codecs {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxSide = 65536;
constexpr int64_t kMaxPixels = int64_t(1) << 28;

template <class Int>
void scaleIntegers(const std::vector<Int>& raw, std::vector<float>& out, float max) {
    out.resize(raw.size());
    for (size_t i = 0; i < raw.size(); ++i)
        out[i] = static_cast<float>(raw[i]) / max;
}

bool isFloatType(OIIO::TypeDesc type) {
    return type.basetype == OIIO::TypeDesc::HALF || type.basetype == OIIO::TypeDesc::FLOAT ||
           type.basetype == OIIO::TypeDesc::DOUBLE;
}

}  // namespace

namespace {

enum class Dimensions { Flat, Volume };

Result<Image> readImageFile(const fs::path& file, Dimensions dimensions) {
    std::error_code ec;
    if (!fs::exists(file, ec))
        return imageFileError(file, "no such file");
    if (!fs::is_regular_file(file, ec))
        return imageFileError(file, "not a regular file");

    // Without this hint OpenImageIO premultiplies PNG/TGA colour by alpha on read.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(file.string(), &config);
    if (!in)
        return imageFileError(file, "cannot read image: " + oneLine(OIIO::geterror()));

    const OIIO::ImageSpec spec = in->spec();
    const int depth = std::max(spec.depth, 1);
    if (spec.width <= 0 || spec.height <= 0)
        return imageFileError(file, "image has no pixels (" + std::to_string(spec.width) + "x" +
                                   std::to_string(spec.height) + ")");
    if (spec.width > kMaxSide || spec.height > kMaxSide || depth > kMaxSide ||
        int64_t(spec.width) * spec.height * depth > kMaxPixels)
        return imageFileError(file, "image too large (" + std::to_string(spec.width) + "x" +
                                   std::to_string(spec.height) + (depth > 1 ? "x" + std::to_string(depth) : "") + ")");
    if (Result<void> memory = checkImageMemory(file, spec.width, spec.height, depth, std::min(spec.nchannels, 4)); !memory)
        return Error{memory.error()};
    if (dimensions == Dimensions::Flat && depth > 1)
        return imageFileError(file, "a volume image (" + std::to_string(depth) +
                                   " slices): it can only be a volume texture (<volume>, RenderMonkey's Rm3DTextureVariable)");
    if (dimensions == Dimensions::Volume && depth == 1)
        return imageFileError(file, "a 2D image, not a volume: a volume texture needs a file with depth, such as a DDS volume texture");
    // OpenImageIO 2.4 decodes only the first slice of a block-compressed DDS volume (the others
    // come back zero): rmfx decodes those itself.
    const std::string compression = spec.get_string_attribute("compression");
    if (depth > 1 && compression.rfind("DXT", 0) == 0) {
        in->close();
        return readBlockCompressedDdsVolume(file);
    }
    if (spec.nchannels < 1)
        return imageFileError(file, "unsupported channel count " + std::to_string(spec.nchannels));

    Image image;
    image.width = spec.width;
    image.height = spec.height;
    image.depth = depth;
    image.channels = std::min(spec.nchannels, 4);
    image.highDynamicRange = isFloatType(spec.format);
    image.bitsPerChannel = static_cast<int>(spec.format.size() * 8);

    // 8- and 16-bit data is read as it is stored and scaled here, so that a byte b becomes
    // exactly b / 255.0f (OpenImageIO's own conversion multiplies by a rounded reciprocal).
    const size_t count = size_t(image.width) * image.height * image.depth * image.channels;
    bool ok = false;
    if (spec.format.basetype == OIIO::TypeDesc::UINT8) {
        std::vector<uint8_t> raw(count);
        ok = in->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::UINT8, raw.data());
        if (ok) scaleIntegers(raw, image.pixels, 255.0f);
    } else if (spec.format.basetype == OIIO::TypeDesc::UINT16) {
        std::vector<uint16_t> raw(count);
        ok = in->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::UINT16, raw.data());
        if (ok) scaleIntegers(raw, image.pixels, 65535.0f);
    } else {
        image.pixels.resize(count);
        ok = in->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::FLOAT, image.pixels.data());
    }
    if (!ok)
        return imageFileError(file, "cannot read pixels: " + oneLine(in->geterror()));
    in->close();
    return image;
}

}  // namespace

Result<Image> readImage(const fs::path& file) { return readImageFile(file, Dimensions::Flat); }

Result<Image> readVolumeImage(const fs::path& file) { return readImageFile(file, Dimensions::Volume); }

}  // namespace rmfx::codecs
