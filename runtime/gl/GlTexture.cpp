#include "gl/GlTexture.h"

#include <algorithm>
#include <cmath>

#include <epoxy/gl.h>

#include "gl/GlFormats.h"
#include "io/image/CubeMapLayout.h"
#include "io/image/DdsCubeMap.h"
#include "io/image/ImageIO.h"
#include "io/image/MipChain.h"

namespace rmfx {
namespace {

struct UploadFormat {
    GLenum internal = GL_RGBA32F;
    GLenum pixelFormat = GL_RGBA;
    bool swizzleGray = false;  // 1 channel: rgb = r; 2 channels: rgb = r, a = g
};

// 8-bit sRGB images of 3 or 4 channels decode in hardware (GL_SRGB8*); every other sRGB image is
// decoded on the CPU first (alpha stays linear).
UploadFormat chooseFormat(Image& image, ColorSpace space) {
    UploadFormat f;
    static constexpr GLenum pixelFormats[5] = {0, GL_RED, GL_RG, GL_RGB, GL_RGBA};
    f.pixelFormat = pixelFormats[image.channels];
    f.swizzleGray = image.channels <= 2;
    bool hardwareSrgb = space == ColorSpace::Srgb && image.bitsPerChannel == 8 && image.channels >= 3;
    if (space == ColorSpace::Srgb && !hardwareSrgb) {
        int colorChannels = image.channels == 2 || image.channels == 4 ? image.channels - 1 : image.channels;
        for (size_t i = 0; i < image.pixels.size(); ++i)
            if (static_cast<int>(i % image.channels) < colorChannels) image.pixels[i] = srgbDecode(image.pixels[i]);
    }
    if (hardwareSrgb) {
        f.internal = image.channels == 4 ? GL_SRGB8_ALPHA8 : GL_SRGB8;
    } else if (image.highDynamicRange || space == ColorSpace::Srgb) {
        static constexpr GLenum floats[5] = {0, GL_R32F, GL_RG32F, GL_RGB32F, GL_RGBA32F};
        f.internal = floats[image.channels];
    } else if (image.bitsPerChannel <= 8) {
        static constexpr GLenum bytes[5] = {0, GL_R8, GL_RG8, GL_RGB8, GL_RGBA8};
        f.internal = bytes[image.channels];
    } else {
        static constexpr GLenum shorts[5] = {0, GL_R16, GL_RG16, GL_RGB16, GL_RGBA16};
        f.internal = shorts[image.channels];
    }
    return f;
}

size_t bytesPerTexel(GLenum internal) {
    switch (internal) {
        case GL_R8: return 1;
        case GL_RG8: case GL_R16: return 2;
        case GL_RGB8: case GL_SRGB8: return 3;
        case GL_RGBA8: case GL_SRGB8_ALPHA8: case GL_RG16: case GL_R32F: return 4;
        case GL_RGB16: return 6;
        case GL_RGBA16: case GL_RG32F: return 8;
        case GL_RGB32F: return 12;
        default: return 16;
    }
}

void applySwizzle(GLuint texture, int channels) {
    if (channels == 1) {
        const GLint swizzle[4] = {GL_RED, GL_RED, GL_RED, GL_ONE};
        glTextureParameteriv(texture, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
    } else if (channels == 2) {
        const GLint swizzle[4] = {GL_RED, GL_RED, GL_RED, GL_GREEN};
        glTextureParameteriv(texture, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
    }
}

// The levels below the base are made on the CPU (io/image/MipChain.h), the same on every driver and
// much cheaper than llvmpipe's glGenerateTextureMipmap, which costs about 150 ms a cube map.
MipEncoding mipEncoding(const UploadFormat& f) {
    return f.internal == GL_SRGB8 || f.internal == GL_SRGB8_ALPHA8 ? MipEncoding::Srgb : MipEncoding::Linear;
}

std::string label(const Texture& t) {
    return std::string(textureElementName(t.kind)) + " '" + t.name + "'";
}

// Image rows run top to bottom. OpenGL's t = 0 is the bottom row: the rows are turned over.
// Direct3D's v = 0 is the top row (topFirst): they are uploaded as they are.
std::vector<float> rowsForUpload(Image& image, bool topFirst) {
    if (topFirst) return std::move(image.pixels);
    std::vector<float> flipped(image.pixels.size());
    const size_t row = static_cast<size_t>(image.width) * image.channels;
    const size_t slice = row * static_cast<size_t>(image.height);
    for (int z = 0; z < std::max(image.depth, 1); ++z)
        for (int y = 0; y < image.height; ++y)
            std::copy_n(image.pixels.begin() + static_cast<long>(z * slice + y * row), row,
                        flipped.begin() + static_cast<long>(z * slice + (image.height - 1 - y) * row));
    return flipped;
}

GlTextureInfo uploadTexture2D(Image image, const Texture& texture, bool topFirst) {
    GlTextureInfo info;
    UploadFormat f = chooseFormat(image, texture.colorSpace);
    info.width = image.width;
    info.height = image.height;
    int levels = texture.mipmaps ? gl::mipLevels(info.width, info.height) : 1;
    std::vector<Image> below = mipLevelsBelow(image, levels, mipEncoding(f));
    const std::vector<float> flipped = rowsForUpload(image, topFirst);
    glCreateTextures(GL_TEXTURE_2D, 1, &info.name);
    glTextureStorage2D(info.name, levels, f.internal, info.width, info.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(info.name, 0, 0, 0, info.width, info.height, f.pixelFormat, GL_FLOAT, flipped.data());
    for (int level = 1; level < levels; ++level) {
        Image& mip = below[static_cast<size_t>(level - 1)];
        glTextureSubImage2D(info.name, level, 0, 0, mip.width, mip.height, f.pixelFormat, GL_FLOAT,
                            rowsForUpload(mip, topFirst).data());
    }
    if (f.swizzleGray) applySwizzle(info.name, image.channels);
    info.bytes = static_cast<size_t>(info.width) * info.height * bytesPerTexel(f.internal) * (texture.mipmaps ? 4 : 3) / 3;
    return info;
}

// Each slice's rows as a 2D texture's are; slice 0 at r = 0, as Direct3D's w = 0.
GlTextureInfo uploadVolume(Image image, const Texture& texture, bool topFirst) {
    GlTextureInfo info;
    UploadFormat f = chooseFormat(image, texture.colorSpace);
    info.width = image.width;
    info.height = image.height;
    const int largest = std::max({image.width, image.height, image.depth});
    const int levels = texture.mipmaps ? static_cast<int>(std::floor(std::log2(largest))) + 1 : 1;
    std::vector<Image> below = mipLevelsBelow(image, levels, mipEncoding(f));
    const std::vector<float> flipped = rowsForUpload(image, topFirst);
    glCreateTextures(GL_TEXTURE_3D, 1, &info.name);
    glTextureStorage3D(info.name, levels, f.internal, image.width, image.height, image.depth);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage3D(info.name, 0, 0, 0, 0, image.width, image.height, image.depth, f.pixelFormat, GL_FLOAT,
                        flipped.data());
    for (int level = 1; level < levels; ++level) {
        Image& mip = below[static_cast<size_t>(level - 1)];
        glTextureSubImage3D(info.name, level, 0, 0, 0, mip.width, mip.height, mip.depth, f.pixelFormat, GL_FLOAT,
                            rowsForUpload(mip, topFirst).data());
    }
    if (f.swizzleGray) applySwizzle(info.name, image.channels);
    info.bytes = static_cast<size_t>(image.width) * image.height * image.depth * bytesPerTexel(f.internal) *
                 (texture.mipmaps ? 8 : 7) / 7;
    return info;
}

}  // namespace

Result<GlTextureInfo> loadGlTexture(const Workspace& ws, const Texture& texture) {
    GlTextureInfo info;
    const bool topFirst = rowsTopFirst(ws.textureSpace);
    Result<CubeFaces> faces = Error{""};
    if (texture.supplied) {
        if (texture.supplied->empty()) return Error{label(texture) + ": the image supplied for it is empty"};
        if (texture.kind == TextureKind::Texture2D) return uploadTexture2D(*texture.supplied, texture, topFirst);
        if (texture.kind == TextureKind::Volume) {
            if (texture.supplied->pixels.size() !=
                static_cast<size_t>(texture.supplied->width) * texture.supplied->height * texture.supplied->depth * texture.supplied->channels)
                return Error{label(texture) + ": the image supplied for it is not a whole volume"};
            return uploadVolume(*texture.supplied, texture, topFirst);
        }
        faces = cubeFromImage(*texture.supplied);  // a placeholder's cross (io/image/PlaceholderImage)
    } else if (texture.files.empty()) {
        return Error{label(texture) + ": no image was given for it (rmfx render --input " + texture.name + "=FILE)"};
    } else if (texture.kind == TextureKind::Texture2D) {
        auto image = readImage(ws.folder / texture.files[0]);
        if (!image) return Error{label(texture) + ": " + image.error()};
        return uploadTexture2D(std::move(*image), texture, topFirst);
    } else if (texture.kind == TextureKind::Volume) {
        auto image = readVolumeImage(ws.folder / texture.files[0]);
        if (!image) return Error{label(texture) + ": " + image.error()};
        return uploadVolume(std::move(*image), texture, topFirst);
    } else if (texture.files.size() == 1 && isDdsFile(texture.files[0])) {
        faces = readDdsCubeMap(ws.folder / texture.files[0]);
    } else if (texture.layout == CubeLayout::Faces) {
        std::array<Image, 6> images;
        for (int i = 0; i < 6; ++i) {
            auto image = readImage(ws.folder / texture.files[i]);
            if (!image) return Error{label(texture) + ": " + image.error()};
            images[i] = std::move(*image);
        }
        faces = cubeFromFaces(std::move(images));
    } else {
        auto image = readImage(ws.folder / texture.files[0]);
        if (!image) return Error{label(texture) + ": " + image.error()};
        faces = texture.layout == CubeLayout::Cross      ? cubeFromCross(*image)
                : texture.layout == CubeLayout::FromImage ? cubeFromImage(*image)
                                                          : cubeFromEquirect(*image, texture.faceSize);
    }
    if (!faces) return Error{label(texture) + ": " + faces.error()};
    CubeFaces& cube = *faces;
    UploadFormat f;
    for (Image& face : cube) f = chooseFormat(face, texture.colorSpace);
    info.width = info.height = cube[0].width;
    int levels = texture.mipmaps ? gl::mipLevels(info.width, info.height) : 1;
    glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &info.name);
    glTextureStorage2D(info.name, levels, f.internal, info.width, info.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // Cube faces are uploaded top row first: GL's face t axis points down the face.
    for (int i = 0; i < 6; ++i) {
        glTextureSubImage3D(info.name, 0, 0, 0, i, info.width, info.height, 1, f.pixelFormat, GL_FLOAT,
                            cube[i].pixels.data());
        int level = 1;
        for (const Image& mip : mipLevelsBelow(cube[i], levels, mipEncoding(f)))
            glTextureSubImage3D(info.name, level++, 0, 0, i, mip.width, mip.height, 1, f.pixelFormat, GL_FLOAT,
                                mip.pixels.data());
    }
    if (f.swizzleGray) applySwizzle(info.name, cube[0].channels);
    info.bytes = static_cast<size_t>(info.width) * info.height * 6 * bytesPerTexel(f.internal) * (texture.mipmaps ? 4 : 3) / 3;
    return info;
}

}  // namespace rmfx
