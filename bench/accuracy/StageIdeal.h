#pragma once
// A stage's ideal for one input, computed once and compared with every variant's output: the
// parameters come from the stage workspace's variables (their defaults as declared).

#include <string>
#include <utility>
#include <vector>

#include "bench/accuracy/AccuracyMetrics.h"
#include "bench/accuracy/VariantManifest.h"
#include "core/Result.h"
#include "model/Image.h"
#include "model/Workspace.h"
#include "reference/CpuImage.h"

namespace rmfx::accuracy {

struct StageIdeal {
    IdealKind kind = IdealKind::Bloom;
    test::RefImage sanitisedInput;  // row 0 at the bottom, as every RefImage
    test::RefImage image;           // bloom, streak: result*; tone map: the display values before the OETF
    double logAverage = 0.0;  // luminance: Lavg*; tone map: the Scene_Luminance it used (Lavg* of S)
    // Variables the bench sets in every variant so that it computes what the ideal does (the tone
    // map's Scene_Luminance = Lavg*).
    std::vector<std::pair<std::string, std::string>> settings;
};

// Errors name the workspace and the variable it lacks.
Result<StageIdeal> computeStageIdeal(IdealKind kind, const Workspace& ws, const Image& input);

// The variant's output against the ideal (AccuracyMetrics.h). An error when its size is not the
// input's (the luminance stage: not at least 1x1).
Result<ErrorMetrics> stageMetrics(const StageIdeal& ideal, const Image& output);

}  // namespace rmfx::accuracy
