#pragma once
// The bench's result files as text: CSV, JSON and a markdown table. (The SVG plot: AccuracyPlot.h.)

#include <string>

#include "bench/accuracy/BenchResults.h"

namespace rmfx::accuracy {

// Header input,stage,variant,effects,settings,frames,median_ms,p10_ms,p90_ms,min_ms,max_ms,
// max_rel_error,mean_rel_error,psnr_db,pareto; then one line per row. PSNR +inf as "inf".
std::string resultsCsv(const BenchResults& results);

// {"device", "size", "frames", "warmup", "date", "command", "rows": [{…the CSV's columns…}]};
// non-finite numbers (an infinite PSNR) are null.
std::string resultsJson(const BenchResults& results);

// Per stage, a table of the rows of input `input` (kAllInputs: the summary), Pareto-front
// variants in bold, with a line saying what the columns are.
std::string resultsMarkdown(const BenchResults& results, const std::string& input);

}  // namespace rmfx::accuracy
