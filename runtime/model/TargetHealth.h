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

// How the check looks at a pass (rmfx render --check-method). WhileDrawing: the pass's own
// fragment shader counts what it writes (gl/HealthInstrumentation.h), where the pass allows it;
// AfterPass: a draw over the target after the pass. Automatic: WhileDrawing on a GPU; on a
// software rasteriser, where the counting code costs every fragment (llvmpipe,
// docs/performance.md), WhileDrawing only in a pass whose neighbour in the schedule writes the
// same target (a scene drawn model by model, where each inspection would read the whole target
// while the counting runs on the model's fragments only), AfterPass in the others.
enum class HealthCheckMethod { Automatic, WhileDrawing, AfterPass };
// "auto", "while-drawing", "after-pass".
const char* healthCheckMethodName(HealthCheckMethod method);
std::optional<HealthCheckMethod> parseHealthCheckMethod(const std::string& name);

// One pass's count of each kind in the target it wrote.
struct PassHealth {
    std::string pass;
    std::string target;
    bool inspected = true;  // false: the target's format cannot show any of the kinds
    // True: the pass's own shader counted what it wrote (gl/HealthInstrumentation.h); false: the
    // check inspected the whole target after the pass.
    bool countedWhileDrawing = false;
    // Counted while drawing by a pass that keeps what its target held where it does not draw (a
    // mesh drawn without clearing colour): its counts are of the pixels it drew, not of the whole
    // target, which may still hold what earlier passes wrote.
    bool ownPixelsOnly = false;
    // With the while-drawing method, why this pass was inspected after it ran instead ("it blends
    // onto its target"); empty otherwise.
    std::string whyNotWhileDrawing;
    std::array<long long, healthKindCount> counts{};
};

// The first pass of a frame whose target held a kind: the first such pixel counting from the
// bottom row, left to right (GL's order, which rasterisers follow: gl/HealthBuffer.h), given in
// reading coordinates (row 0 at the top), its value, and what the pass's 2D inputs held at the
// same place (each input's texel under the pixel's centre; "sampler → target 'x'" or "… →
// texture 'y'").
struct HealthFinding {
    HealthKind kind = HealthKind::NaN;
    int frame = 0;  // counted from 0
    std::string pass;
    std::string target;
    long long count = 0;  // pixels of that pass holding the kind
    glm::ivec2 pixel{0};
    // False when the pixel's value and inputs were not kept: a pass counting its own writes keeps
    // them for the first few fragments that lowered the first pixel (gl/HealthBuffer.h).
    bool recorded = true;
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
