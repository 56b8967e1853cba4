#include "bench/accuracy/TimeSummary.h"

#include <algorithm>

#include "core/Percentile.h"

namespace rmfx::accuracy {

TimeSummary summariseTimes(std::vector<double> ms) {
    TimeSummary out;
    out.frames = static_cast<int>(ms.size());
    if (ms.empty()) return out;
    std::sort(ms.begin(), ms.end());
    auto at = [&](double p) { return percentileOfSorted(ms, p); };
    out.median = at(0.5);
    out.p10 = at(0.1);
    out.p90 = at(0.9);
    out.min = ms.front();
    out.max = ms.back();
    return out;
}

}  // namespace rmfx::accuracy
