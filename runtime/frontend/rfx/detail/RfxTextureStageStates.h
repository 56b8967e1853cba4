#pragma once
// Direct3D texture stage states (an RmTextureObject's RmState USAGE="TEXTURE_STATE",
// D3DTEXTURESTAGESTATETYPE numbers), which share their numbers with the sampler states but are
// not sampler states. With shaders running, Direct3D used only the bump-mapping ones, which the
// assembly instructions texbem, texbeml and bem read.

#include <array>

#include "frontend/rfx/detail/RfxElement.h"

namespace rmfx::rfx {

struct TextureStageStates {
    std::array<float, 4> bumpMatrix{};  // D3DTSS_BUMPENVMAT00, 01, 10, 11 (Direct3D's default: 0)
    float bumpScale = 0.0f;             // D3DTSS_BUMPENVLSCALE
    float bumpOffset = 0.0f;            // D3DTSS_BUMPENVLOFFSET
};

// Reads one texture stage state of stage `stage` into `into`. The fixed-function blending states
// (COLOROP … RESULTARG, CONSTANT), which Direct3D ignored while a pixel shader ran, are skipped;
// a texture coordinate index or transform other than the default is a warning (rmfx's passes
// always have shaders); any other number is a warning naming it.
void applyTextureStageState(const RfxElement& state, int stage, TextureStageStates& into);

}  // namespace rmfx::rfx
