#include "core/MedianInterval.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/Percentile.h"

namespace rmfx {

double binomialHalfAtMost(int n, int k) {
    if (k < 0) return 0.0;
    if (k >= n) return 1.0;
    // Each term C(n, i)·2^−n in logarithms: 2^−n alone underflows past n = 1074.
    const double logHalfN = -n * std::log(2.0);
    double sum = 0.0;
    for (int i = 0; i <= k; ++i)
        sum += std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) + logHalfN);
    return std::min(sum, 1.0);
}

MedianInterval medianInterval(std::vector<double> samples, double confidence) {
    assert(!samples.empty() && confidence > 0.0 && confidence < 1.0);
    std::sort(samples.begin(), samples.end());
    const int n = static_cast<int>(samples.size());
    MedianInterval out;
    out.samples = n;
    out.median = percentileOfSorted(samples, 0.5);
    // The largest k whose two tails together stay within 1 − confidence.
    int k = 1;
    while (k + 1 <= (n + 1) / 2 && 2.0 * binomialHalfAtMost(n, k) <= 1.0 - confidence) ++k;
    out.low = samples[static_cast<size_t>(k - 1)];
    out.high = samples[static_cast<size_t>(n - k)];
    out.coverage = 1.0 - 2.0 * binomialHalfAtMost(n, k - 1);
    return out;
}

}  // namespace rmfx
