#include "io/image/DdsCubeMap.h"
#include "io/image/codecs/CodecFunctions.h"

#include <algorithm>

#include <OpenImageIO/imageio.h>

#include "io/image/ImageIO.h"

namespace rmfx::codecs {

Result<CubeFaces> readDdsCubeMap(const std::filesystem::path& file) {
    std::string name = "'" + file.string() + "'";
    {
        auto in = OIIO::ImageInput::open(file.string());
        if (!in) return Error{name + ": cannot read image: " + OIIO::geterror()};
        const OIIO::ImageSpec& spec = in->spec();
        std::string format = spec.get_string_attribute("textureformat");
        std::string sides = spec.get_string_attribute("dds:CubeMapSides");
        if (spec.depth > 1 || format == "Volume Texture")
            return Error{name + " is a volume texture (depth " + std::to_string(spec.depth) +
                         "), not a cube map: declare it a <volume>"};
        if (format != "CubeFace Environment")
            return Error{name + " is a 2D DDS texture, not a cube map: use it as a texture, or give six faces"};
        if (sides != "+x -x +y -y +z -z")
            return Error{name + " is a cube map with only the faces '" + sides + "': a cube texture needs all six"};
    }
    auto image = readImage(file);
    if (!image) return Error{image.error()};
    if (image->height != 6 * image->width)
        return Error{name + ": a cube map of " + std::to_string(image->width) + "x" + std::to_string(image->height) +
                     " texels, not six square faces"};
    std::array<Image, 6> faces;
    size_t faceValues = static_cast<size_t>(image->width) * image->width * image->channels;
    for (size_t i = 0; i < 6; ++i) {
        Image& face = faces[i];
        face.width = face.height = image->width;
        face.channels = image->channels;
        face.highDynamicRange = image->highDynamicRange;
        face.bitsPerChannel = image->bitsPerChannel;
        face.pixels.assign(image->pixels.begin() + static_cast<long>(i * faceValues),
                           image->pixels.begin() + static_cast<long>((i + 1) * faceValues));
    }
    return cubeFromFaces(std::move(faces));
}

}  // namespace rmfx::codecs
