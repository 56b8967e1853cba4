#pragma once
// What stands in for a texture whose image file is missing (--missing-media placeholder): a
// magenta and dark grey checker, 8 texels a square, that no effect shows on purpose. A 2D texture
// gets 64x64; a cube map a 4:3 cross of 32x32 faces (io/image/CubeMapLayout reads it); a volume
// 32x32x32, checkered in depth too.

#include "model/Image.h"
#include "model/Workspace.h"

namespace rmfx {

inline constexpr float kPlaceholderMagenta[3] = {1.0f, 0.0f, 1.0f};
inline constexpr float kPlaceholderGrey = 0.2f;

Image placeholderImage(TextureKind kind);

}  // namespace rmfx
