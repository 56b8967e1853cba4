#include "frontend/rfx/detail/RfxTextureStageStates.h"

#include "frontend/rfx/detail/RfxRenderStates.h"

namespace rmfx::rfx {

void applyTextureStageState(const RfxElement& state, int stage, TextureStageStates& into) {
    auto number = state.integer("STATE", 0, 4294967295LL);
    if (!number) return;
    const bool isFloat = (*number >= 7 && *number <= 10) || *number == 22 || *number == 23;
    auto value = stateValue(state, isFloat);
    if (!value) return;
    switch (*number) {
        case 7: case 8: case 9: case 10: into.bumpMatrix[static_cast<size_t>(*number - 7)] = floatFromBits(*value); return;
        case 22: into.bumpScale = floatFromBits(*value); return;
        case 23: into.bumpOffset = floatFromBits(*value); return;
        case 1: case 2: case 3: case 4: case 5: case 6: case 26: case 27: case 28: case 32: return;
        case 11:  // D3DTSS_TEXCOORDINDEX: fixed-function vertex processing only
            if ((*value & 0xFFFF) != stage || (*value & ~0xFFFFLL) != 0)
                state.warning("D3DTSS_TEXCOORDINDEX = " + std::to_string(*value) +
                              ": only fixed-function vertex processing read it, and rmfx's passes have vertex shaders; ignored");
            return;
        case 24:  // D3DTSS_TEXTURETRANSFORMFLAGS
            if (*value != 0)
                state.warning("D3DTSS_TEXTURETRANSFORMFLAGS = " + std::to_string(*value) +
                              ": texture coordinate transforms are fixed-function vertex processing; ignored");
            return;
        default:
            state.warning("texture stage state " + std::to_string(*number) + " = " + std::to_string(*value) +
                          " has no equivalent in rmfx; ignored");
    }
}

}  // namespace rmfx::rfx
