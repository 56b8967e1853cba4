#pragma once
// A confidence interval for the median that assumes nothing of the distribution: in n independent
// samples of it, the number below the true median is binomial(n, 1/2), so the median lies between
// the k-th and the (n − k + 1)-th smallest sample (1-based) with probability
// 1 − 2·P(binomial(n, 1/2) ≤ k − 1). The interval is the narrowest such pair whose probability is
// at least the one asked for; with too few samples (fewer than 6 for 0.95) it is the minimum and
// maximum, and `coverage` says how sure that is.

#include <vector>

namespace rmfx {

struct MedianInterval {
    double median = 0.0;  // as core/Percentile.h defines it
    double low = 0.0, high = 0.0;
    double coverage = 0.0;  // the probability that the true median lies in [low, high]
    int samples = 0;
};

// At least one sample, in any order; 0 < confidence < 1.
MedianInterval medianInterval(std::vector<double> samples, double confidence = 0.95);

// P(binomial(n, 1/2) ≤ k), for 0 ≤ n (k < 0 gives 0).
double binomialHalfAtMost(int n, int k);

}  // namespace rmfx
