#pragma once
// Reads a workspace texture's image files and uploads them as a GL texture (2D or cube map),
// with mipmaps when asked. Needs a current GL context.

#include "core/Result.h"
#include "model/Workspace.h"

namespace rmfx {

struct GlTextureInfo {
    unsigned name = 0;  // GL texture object; the caller deletes it
    int width = 0, height = 0;
    size_t bytes = 0;
};

// 2D and volume images are uploaded with their top row at t = 0 in a Direct3D texture space
// (rowsTopFirst), at t = 1 in OpenGL's; cube faces top row first in both, as GL's faces are laid out.
Result<GlTextureInfo> loadGlTexture(const Workspace& ws, const Texture& texture);

}  // namespace rmfx
