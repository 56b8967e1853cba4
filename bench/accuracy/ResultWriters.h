#pragma once
// The bench's result files as text: CSV, JSON and a markdown table. (The SVG plot: AccuracyPlot.h.)

#include <string>

#include "bench/accuracy/BenchResults.h"

namespace rmfx::accuracy {

// Header input,stage,variant,effects,settings,frames,median_ms,p10_ms,p90_ms,min_ms,max_ms,
// max_rel_error,mean_rel_error,psnr_db,pareto,wall_median_ms,wall_p10_ms,wall_p90_ms; then one
// line per row (the *_ms without wall_: GPU timer queries). PSNR +inf as "inf".
std::string resultsCsv(const BenchResults& results);

// {"device", "size", "frames", "warmup", "date", "command", "ranked_time", "rows": [{…the CSV's
// columns…}]};
// non-finite numbers (an infinite PSNR) are null.
std::string resultsJson(const BenchResults& results);

// Per stage, a table of the rows of input `input` (kAllInputs: the summary) with the ranked time,
// Pareto-front variants in bold.
std::string resultsMarkdown(const BenchResults& results, const std::string& input);

}  // namespace rmfx::accuracy
