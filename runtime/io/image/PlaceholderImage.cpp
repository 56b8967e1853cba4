#include "io/image/PlaceholderImage.h"

namespace rmfx {

Image placeholderImage(TextureKind kind) {
    Image image;
    const bool volume = kind == TextureKind::Volume;
    image.width = kind == TextureKind::Cube ? 4 * 32 : volume ? 32 : 64;
    image.height = kind == TextureKind::Cube ? 3 * 32 : volume ? 32 : 64;
    image.depth = volume ? 32 : 1;
    image.channels = 4;
    image.pixels.resize(static_cast<size_t>(image.width) * image.height * image.depth * 4);
    float* texel = image.pixels.data();
    for (int z = 0; z < image.depth; ++z)
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x, texel += 4) {
                const bool magenta = ((x / 8) + (y / 8) + (z / 8)) % 2 == 0;
                for (int c = 0; c < 3; ++c) texel[c] = magenta ? kPlaceholderMagenta[c] : kPlaceholderGrey;
                texel[3] = 1.0f;
            }
    return image;
}

}  // namespace rmfx
