#pragma once
// Measuring one variant of a stage on one input: its stage workspace with texture `Input` reading
// the input, the variant's effect and settings, GPU time per frame from timer queries (and the
// wall clock of renderFrame + glFinish) after warm-up frames, and the output target read back. Needs a current GL context.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "bench/accuracy/TimeSummary.h"
#include "bench/accuracy/VariantManifest.h"
#include "core/Result.h"
#include "model/Image.h"
#include "model/Workspace.h"
#include "validation/Validation.h"

namespace rmfx::accuracy {

struct VariantMeasurement {
    TimeSummary time;  // GPU timer queries
    TimeSummary wall;  // wall clock of renderFrame + glFinish
    Image output;
};

struct FrameCounts {
    int warmup = 3;
    int frames = 20;
};

// `stageWorkspace`: the stage's workspace as loaded (copied here, not changed). `extra`: settings
// after the variant's own (the tone-map stage's Scene_Luminance). Errors name the stage, the
// variant and what failed. `programs`: validation's, from loading the stage's workspace.
Result<VariantMeasurement> measureVariant(const Workspace& stageWorkspace, const StageSpec& stage, const Variant& variant,
                                          const std::filesystem::path& inputFile, glm::ivec2 size,
                                          const std::vector<std::pair<std::string, std::string>>& extra,
                                          const FrameCounts& counts, const CheckedPrograms* programs = nullptr);

}  // namespace rmfx::accuracy
