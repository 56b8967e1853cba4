#pragma once
// rmfx render --check inside the passes themselves: a pass's fragment shader, made to count what
// it writes, costs no draw and no wait of its own, where an inspection after the pass (a draw
// over the target that must wait for the pass, and that the next pass must wait for) costs a
// GPU about as much as a small pass. The pass's own main() runs first (renamed by a #define
// after #version); the added main() then reads the output at location 0, classifies each
// channel as the target's format will hold it (NaN, ±Inf, negative, at or beyond the format's
// largest) and counts it in the health buffer (HealthBuffer.h), with the pixel's value as written
// and its 2D inputs' texels there.
//
// A pass counts itself only where what its fragments write is what the target holds: no
// blending and no alpha test; with a depth test, only when the shader neither discards nor writes
// gl_FragDepth, so that the test can run before the shader (early_fragment_tests) and occluded
// fragments are not counted. The shader must be GLSL 3.30 or later (desktop), write its colour to
// one non-array float output at location 0, and read every 2D input as a sampler2D of its own.
// Other passes are inspected after they ran (GlHealthCheck). What a pass counts is then what it
// wrote: a pixel written twice by a pass counts twice, which a pass drawing a model with its depth
// test can do.

#include <string>
#include <vector>

#include "core/Result.h"
#include "model/TargetHealth.h"
#include "model/Workspace.h"

namespace rmfx {

// The fragment shader `fragmentCode` (as compiled into `program`, linked) counting what it
// writes, reading `inputSamplers` at the pixel; or why the pass cannot count itself.
Result<std::string> instrumentForHealth(const Pass& pass, const std::string& fragmentCode, unsigned program,
                                        const std::vector<std::string>& inputSamplers, int bufferBinding);

// The uniforms instrumentForHealth adds, in a program linked from its code; `found` false when
// the program lacks any of them. Uniforms named rmfx_health_* are never workspace variables.
struct HealthUniforms {
    bool found = false;
    int slot = -1, records = -1, size = -1, channels = -1, negativeAbove = -1, below = -1;
    // What they were last set to: a pass draws the same way frame after frame, and each uniform
    // call is CPU time in a frame that a GPU may finish sooner.
    struct Values {
        size_t position = static_cast<size_t>(-1), capacity = 0;
        glm::ivec2 size{0};
        TargetFormat format = TargetFormat::RGBA8;
        bool operator==(const Values&) const = default;
    };
    mutable Values set;
};
HealthUniforms findHealthUniforms(unsigned program);

// Sets them, where they changed, for a draw of the pass at schedule position `position` into a
// target of `format` and `size`, whose buffer holds `capacity` positions. Needs the program
// current.
void setHealthUniforms(const HealthUniforms& uniforms, size_t position, size_t capacity, glm::ivec2 size, TargetFormat format);

}  // namespace rmfx
