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
    TimeSummary time;  // GPU: timer queries, first pass start to last pass end
    TimeSummary wall;  // wall clock of renderFrame + glFinish
    ErrorMetrics error;
    bool pareto = false;
};

// Which time the table, the plot and the Pareto front use. GPU timer queries are the measure on a
// GPU; on Mesa llvmpipe they are not: its timestamps are per rasteriser thread, and a frame's span
// between them misses most of the rasterising (a full-screen copy at 512x512 reads 0.05 ms of
// timer-query time against about 15 ms of renderFrame + glFinish), so there the wall clock ranks.
enum class TimeSource { Gpu, Wall };
const char* timeSourceName(TimeSource source);  // "gpu", "wall"
// The axis title and table header for the source: "median GPU time per frame (timer queries), ms".
const char* timeSourceTitle(TimeSource source);

struct BenchResults {
    std::string device;   // GL_VERSION, GL_RENDERER and the EGL platform
    std::string size;     // "512x512", or what the inputs had
    int frames = 0;
    int warmup = 0;
    std::string date;     // UTC, ISO 8601
    std::string command;  // the command line that produced it
    TimeSource ranked = TimeSource::Gpu;
    std::vector<BenchRow> rows;
};

inline constexpr const char* kAllInputs = "all";

inline const TimeSummary& rankedTime(const BenchResults& results, const BenchRow& row) {
    return results.ranked == TimeSource::Gpu ? row.time : row.wall;
}

// Adds the "all" rows: per stage × variant (in first-seen order), the mean over inputs of each
// time and of the mean error, the largest max error and the smallest PSNR.
void addSummaryRows(BenchResults& results);

// Sets `pareto` on every row: the front over (ranked median time, mean relative error) within each
// input × stage group.
void markParetoFronts(BenchResults& results);

}  // namespace rmfx::accuracy
