#include "bench/accuracy/ParetoFront.h"

#include <cmath>

namespace rmfx::accuracy {

std::vector<bool> paretoFront(const std::vector<TimeError>& points) {
    auto valid = [](const TimeError& p) { return !std::isnan(p.time) && !std::isnan(p.error); };
    std::vector<bool> front(points.size(), false);
    for (size_t i = 0; i < points.size(); ++i) {
        if (!valid(points[i])) continue;
        bool dominated = false;
        for (size_t j = 0; j < points.size() && !dominated; ++j) {
            if (j == i || !valid(points[j])) continue;
            const TimeError &a = points[j], &b = points[i];
            dominated = a.time <= b.time && a.error <= b.error && (a.time < b.time || a.error < b.error);
        }
        front[i] = !dominated;
    }
    return front;
}

}  // namespace rmfx::accuracy
