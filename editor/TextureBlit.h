#pragma once
// Draws a texture into the bound framebuffer's viewport with a display transform: how the editor
// shows the effect's output in the window (1:1, texel for pixel, with the workspace's output
// transform, so the window shows what `rmfx render` writes to a PNG) and makes the thumbnails of
// render targets and slices of volume textures (filtered down, sRGB). Its own sampler object makes any target texture complete
// whatever its filter state. Needs a current GL 4.5 context.

#include <memory>
#include <string>

#include <glm/vec2.hpp>

#include "core/Result.h"
#include "model/Image.h"

namespace rmfx::editor {

class TextureBlit {
public:
    static Result<std::unique_ptr<TextureBlit>> create();
    ~TextureBlit();
    TextureBlit(const TextureBlit&) = delete;
    TextureBlit& operator=(const TextureBlit&) = delete;

    // Whether the textures drawn next hold the picture's top row at GL's row 0, as a workspace in a
    // Direct3D texture space draws its targets and uploads its images (model/Workspace.h
    // rowsTopFirst); they are drawn the right way up either way. Default: false (OpenGL's).
    void setRowsTopFirst(bool topFirst);
    // The picture's bottom-left texel lands on framebuffer pixel `origin` (GL's bottom-left origin) and
    // each texel on one pixel: the viewport, from `origin`, covers the texels to draw (the texture's
    // size for all of it).
    void drawExact(unsigned texture, glm::ivec2 origin, DisplayTransform transform);
    // The whole texture stretched over the viewport (bilinear down, nearest up), × 2^exposureStops.
    void drawFiltered(unsigned texture, float exposureStops, DisplayTransform transform);
    // One slice of a volume (3D) texture stretched over the viewport, filtered: `depth` in [0, 1]
    // (r), the texel centres of slice k of n at (k + 0.5) / n.
    void drawSlice(unsigned volume, float depth, DisplayTransform transform);

private:
    TextureBlit() = default;
    void draw(unsigned texture, unsigned sampler, bool exact, glm::ivec2 origin, float scale, DisplayTransform transform);
    unsigned program_ = 0;
    unsigned vertexArray_ = 0;
    unsigned nearest_ = 0, linear_ = 0;
    int exactLocation_ = -1, originLocation_ = -1, scaleLocation_ = -1, srgbLocation_ = -1;
    int slicedLocation_ = -1, sliceLocation_ = -1, topRowFirstLocation_ = -1;
};

}  // namespace rmfx::editor
