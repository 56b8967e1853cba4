#include "core/Percentile.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace rmfx {

double percentileOfSorted(std::span<const double> sorted, double p) {
    assert(!sorted.empty());
    double position = std::clamp(p, 0.0, 1.0) * static_cast<double>(sorted.size() - 1);
    size_t below = static_cast<size_t>(std::floor(position));
    size_t above = std::min(below + 1, sorted.size() - 1);
    double t = position - static_cast<double>(below);
    return sorted[below] + t * (sorted[above] - sorted[below]);
}

double percentile(std::vector<double> samples, double p) {
    std::sort(samples.begin(), samples.end());
    return percentileOfSorted(samples, p);
}

}  // namespace rmfx
