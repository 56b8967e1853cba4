#include "io/image/PlaceholderImage.h"

namespace rmfx {

Image placeholderImage(TextureKind kind) {
    Image image;
    image.width = kind == TextureKind::Cube ? 4 * 32 : 64;
    image.height = kind == TextureKind::Cube ? 3 * 32 : 64;
    image.channels = 4;
    image.pixels.resize(static_cast<size_t>(image.width) * image.height * 4);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const bool magenta = ((x / 8) + (y / 8)) % 2 == 0;
            for (int c = 0; c < 3; ++c) image.at(x, y, c) = magenta ? kPlaceholderMagenta[c] : kPlaceholderGrey;
            image.at(x, y, 3) = 1.0f;
        }
    return image;
}

}  // namespace rmfx
