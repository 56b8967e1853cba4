#pragma once
// The spread of a variant's per-frame GPU times.

#include <vector>

namespace rmfx::accuracy {

struct TimeSummary {
    int frames = 0;
    double median = 0.0, p10 = 0.0, p90 = 0.0, min = 0.0, max = 0.0;  // milliseconds
};

// Percentiles as core/Percentile.h defines them (linear interpolation between closest ranks).
TimeSummary summariseTimes(std::vector<double> milliseconds);

}  // namespace rmfx::accuracy
