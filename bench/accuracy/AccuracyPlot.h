#pragma once
// The error-against-time plot as SVG, written by our own code: one panel per stage, x the median
// time per frame (log; the GPU or wall time, as BenchResults::ranked says), y the mean relative luminance error (log), each variant a numbered dot
// with its p10–p90 time as a horizontal bar, the Pareto front filled and joined by a step line,
// and a legend of the numbers with each variant's PSNR (capped at 100 dB, said on the plot).

#include <string>

#include "bench/accuracy/BenchResults.h"

namespace rmfx::accuracy {

// Plots the rows of input `input` (kAllInputs: the summary over inputs).
std::string accuracyPlotSvg(const BenchResults& results, const std::string& input);

}  // namespace rmfx::accuracy
