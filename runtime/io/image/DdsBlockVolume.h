#pragma once
// A block-compressed (DXT1 … DXT5) DDS volume texture, decoded here: OpenImageIO 2.4 decodes only
// the first slice of one and returns the others as zero. The S3TC rules: a 4x4 block of texels
// per 8 bytes (DXT1: two RGB565 end points and a 2-bit index per texel; with c0 <= c1 the fourth
// colour is transparent black) or 16 bytes (DXT2/3: a 4-bit alpha per texel before the colour
// block; DXT4/5: two alpha end points and a 3-bit index per texel), the colour block of DXT2…5
// always in its four-colour mode. DXT2 and DXT4 hold colour premultiplied by alpha, which is kept.

#include <filesystem>

#include "core/Result.h"
#include "model/Image.h"

namespace rmfx {

// The first mip level of every slice, as RGBA in the file's order (row 0 the top row, slice 0
// first), values byte / 255. Errors name the file: not a DDS volume, not DXT-compressed, truncated.
Result<Image> readBlockCompressedDdsVolume(const std::filesystem::path& file);

}  // namespace rmfx
