#pragma once
// What `rmfx bench` measured: one row per input × stage × variant, and per stage × variant the
// summary over all inputs (input "all"), with the Pareto front marked in each group.

#include <string>
#include <vector>

#include "bench/accuracy/AccuracyMetrics.h"
#include "bench/accuracy/TimeSummary.h"

namespace rmfx::accuracy {

struct BenchRow {
    std::string input;  // a scene or EXR name; "all" for the summary over inputs
    std::string stage;
    std::string variant;
    std::string effects;
    std::string settings;  // "Downsample=1 Target_Format=1"
    TimeSummary time;
    ErrorMetrics error;
    bool pareto = false;
};

struct BenchResults {
    std::string device;   // GL_VERSION, GL_RENDERER and the EGL platform
    std::string size;     // "512x512", or what the inputs had
    int frames = 0;
    int warmup = 0;
    std::string date;     // UTC, ISO 8601
    std::string command;  // the command line that produced it
    std::vector<BenchRow> rows;
};

inline constexpr const char* kAllInputs = "all";

// Adds the "all" rows: per stage × variant (in first-seen order), the mean over inputs of each
// time and of the mean error, the largest max error and the smallest PSNR.
void addSummaryRows(BenchResults& results);

// Sets `pareto` on every row: the front over (median time, mean relative error) within each
// input × stage group.
void markParetoFronts(BenchResults& results);

}  // namespace rmfx::accuracy
