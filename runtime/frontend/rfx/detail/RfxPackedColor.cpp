#include "frontend/rfx/detail/RfxPackedColor.h"

#include <cstdint>

namespace rmfx::rfx {

glm::vec4 unpackArgb(long long packed) {
    auto bits = static_cast<uint32_t>(static_cast<uint64_t>(packed));
    auto channel = [&](int shift) { return static_cast<float>((bits >> shift) & 0xFFu) / 255.0f; };
    return {channel(16), channel(8), channel(0), channel(24)};
}

}  // namespace rmfx::rfx
