#pragma once
// One render target viewed large in its own window: read back once per frame, decoded ("decode
// as" an HDR encoding), scaled by its own exposure, sRGB-encoded; under the cursor, the texel's
// stored and decoded float values.

#include <string>

#include <glm/vec2.hpp>

#include "editor/DisplayTexture.h"
#include "editor/TargetDecoding.h"
#include "gl/GlExecutor.h"

namespace rmfx::editor {

class TargetViewer {
public:
    // `transform`: how the picture starts (sRGB for linear data; the output's own transform for it).
    TargetViewer(std::string target, DisplayTransform transform) : target_(std::move(target)), srgb_(transform == DisplayTransform::Srgb) {}
    const std::string& target() const { return target_; }

    // Reads the target, updates the picture and draws the window, first placed at `firstPosition`
    // with `firstSize` (window coordinates). `written`: whether the last frame wrote the target.
    // Returns false once the user closed the window.
    bool draw(const GlExecutor& executor, glm::vec2 firstPosition, glm::vec2 firstSize, bool written);

private:
    std::string target_;
    float exposureStops_ = 0.0f;
    DecodeAs decode_ = DecodeAs::None;
    bool srgb_ = true;
    DisplayTexture texture_;
    bool open_ = true;
};

}  // namespace rmfx::editor
