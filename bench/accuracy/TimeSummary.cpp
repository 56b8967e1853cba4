#include "bench/accuracy/TimeSummary.h"

#include <algorithm>
#include <cmath>

namespace rmfx::accuracy {

TimeSummary summariseTimes(std::vector<double> ms) {
    TimeSummary out;
    out.frames = static_cast<int>(ms.size());
    if (ms.empty()) return out;
    std::sort(ms.begin(), ms.end());
    auto at = [&](double p) {
        double position = p * static_cast<double>(ms.size() - 1);
        size_t below = static_cast<size_t>(std::floor(position));
        size_t above = std::min(below + 1, ms.size() - 1);
        double t = position - static_cast<double>(below);
        return ms[below] + t * (ms[above] - ms[below]);
    };
    out.median = at(0.5);
    out.p10 = at(0.1);
    out.p90 = at(0.9);
    out.min = ms.front();
    out.max = ms.back();
    return out;
}

}  // namespace rmfx::accuracy
