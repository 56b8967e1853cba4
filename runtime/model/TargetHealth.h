#pragma once
// Numeric health of render targets (rmfx render --check, docs/replay.md): what each pass left in
// its target that a later pass or the viewer will trip over (NaN, ±Inf, negative values, values
// at the largest its format holds), and for each kind the first pass that produced it, with a
// pixel, its value and the pass's inputs there.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "model/Workspace.h"

namespace rmfx {

enum class HealthKind { NaN, PositiveInfinity, NegativeInfinity, Negative, AtFormatMax };
inline constexpr int healthKindCount = 5;
inline constexpr std::array<HealthKind, healthKindCount> allHealthKinds{
    HealthKind::NaN, HealthKind::PositiveInfinity, HealthKind::NegativeInfinity, HealthKind::Negative,
    HealthKind::AtFormatMax};

// "NaN", "+Inf", "-Inf", "negative values", "values at the format's largest".
const char* healthKindName(HealthKind kind);
// NaN and infinities are errors (nothing downstream recovers from them); negatives and values
// at the format's largest are warnings (signed data and saturated highlights can be meant).
bool healthKindIsError(HealthKind kind);

// What a target of `format` can show of each kind. Float formats keep NaN and infinities; only
// signed ones keep negatives; 16-bit and 11/10-bit floats have a largest finite value (per
// channel: 65504 for half, 65024 / 65024 / 64512 for r11g11b10f), at or beyond which a written
// value ends up (rounded to it, or to +Inf). Normalised integer formats clamp whatever is
// written to [0, 1] (or [-1, 1]): nothing of it can be seen there, and they are not inspected.
struct FormatHealthLimits {
    bool inspected = false;
    int channels = 4;
    bool holdsNegatives = false;
    glm::vec4 largest{0.0f};  // per channel; 0: no largest value worth flagging (32-bit floats)
};
FormatHealthLimits formatHealthLimits(TargetFormat format);

// One pass's count of each kind in the target it wrote.
struct PassHealth {
    std::string pass;
    std::string target;
    bool inspected = true;  // false: the target's format cannot show any of the kinds
    std::array<long long, healthKindCount> counts{};
};

// The first pass of a frame whose target held a kind: the first such pixel in reading order
// (row 0 at the top), its value, and what the pass's 2D inputs held at the same place (each
// input's texel under the pixel's centre; "sampler → target 'x'" or "… → texture 'y'").
struct HealthFinding {
    HealthKind kind = HealthKind::NaN;
    int frame = 0;  // counted from 0
    std::string pass;
    std::string target;
    long long count = 0;  // pixels of that pass holding the kind
    glm::ivec2 pixel{0};
    glm::vec4 value{0.0f};
    std::vector<std::pair<std::string, glm::vec4>> inputs;
};

struct FrameHealth {
    std::vector<PassHealth> passes;       // in the order they ran
    std::vector<HealthFinding> findings;  // one per kind found, in HealthKind order
};

// One line for a person: "pass 'bright' wrote NaN into target 'bright' (12 pixels; first at x=3
// y=5: (nan, 0.2, 0.1, 1); there the inputs held: Scene → target 'scene' (1, 2, 3, 1))".
std::string describeFinding(const HealthFinding& finding);

}  // namespace rmfx
