#pragma once
// rmfx's one percentile: linear interpolation between the closest ranks. In the sorted samples
// x[0] ≤ … ≤ x[n−1], the p-th percentile (0 ≤ p ≤ 1) lies at position h = p·(n − 1):
// x[⌊h⌋] + (h − ⌊h⌋)·(x[⌊h⌋+1] − x[⌊h⌋]). (Hyndman and Fan's type 7, numpy's default.) So p = 0
// is the minimum, p = 1 the maximum, and p = 0.5 the median (the mean of the middle two when n
// is even).

#include <span>
#include <vector>

namespace rmfx {

// Samples already sorted ascending, at least one.
double percentileOfSorted(std::span<const double> sorted, double p);
// Any order, at least one sample.
double percentile(std::vector<double> samples, double p);

}  // namespace rmfx
