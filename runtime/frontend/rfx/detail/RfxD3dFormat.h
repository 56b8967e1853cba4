#pragma once
// Direct3D 9 surface formats (D3DFORMAT numbers, as RenderMonkey writes them in
// RmRenderableTexture FORMAT) and the render-target format each becomes.

#include <optional>

#include "model/Workspace.h"

namespace rmfx::rfx {

struct D3dFormat {
    int number;
    const char* name;  // "D3DFMT_A8R8G8B8"
    TargetFormat format;
};

// nullopt: a format rmfx has no render-target format for (depth, compressed, palette…).
std::optional<D3dFormat> d3dFormat(long long number);

}  // namespace rmfx::rfx
