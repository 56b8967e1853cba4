#pragma once
// The Pareto front of (time, error) points, both lower-is-better.

#include <vector>

namespace rmfx::accuracy {

struct TimeError {
    double time = 0.0;
    double error = 0.0;
};

// front[i]: no other point is at least as fast and at least as accurate and strictly better in one.
// Equal points are all on the front. A point with a NaN coordinate is never on it and dominates none.
std::vector<bool> paretoFront(const std::vector<TimeError>& points);

}  // namespace rmfx::accuracy
