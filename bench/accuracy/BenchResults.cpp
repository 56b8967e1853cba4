#include "bench/accuracy/BenchResults.h"

#include <algorithm>
#include <map>

#include "bench/accuracy/ParetoFront.h"

namespace rmfx::accuracy {

const char* timeSourceName(TimeSource source) { return source == TimeSource::Gpu ? "gpu" : "wall"; }

const char* timeSourceTitle(TimeSource source) {
    return source == TimeSource::Gpu ? "median GPU time per frame (timer queries), ms"
                                     : "median wall time per frame (renderFrame + glFinish), ms";
}

namespace {

void addMean(TimeSummary& sum, const TimeSummary& t, double n) {
    sum.median += t.median / n;
    sum.p10 += t.p10 / n;
    sum.p90 += t.p90 / n;
    sum.min += t.min / n;
    sum.max += t.max / n;
}

}  // namespace

void addSummaryRows(BenchResults& results) {
    std::vector<std::pair<std::string, std::string>> order;
    std::map<std::pair<std::string, std::string>, std::vector<const BenchRow*>> groups;
    for (const BenchRow& row : results.rows) {
        if (row.input == kAllInputs) continue;
        auto key = std::pair{row.stage, row.variant};
        if (groups[key].empty()) order.push_back(key);
        groups[key].push_back(&row);
    }
    std::vector<BenchRow> summary;
    for (const auto& key : order) {
        const auto& rows = groups[key];
        BenchRow s = *rows.front();
        s.input = kAllInputs;
        s.time = {};
        s.wall = {};
        s.time.frames = rows.front()->time.frames;
        s.wall.frames = rows.front()->wall.frames;
        s.error = {0.0, 0.0, rows.front()->error.psnrDb};
        double n = static_cast<double>(rows.size());
        for (const BenchRow* r : rows) {
            addMean(s.time, r->time, n);
            addMean(s.wall, r->wall, n);
            s.error.meanRelative += r->error.meanRelative / n;
            s.error.maxRelative = std::max(s.error.maxRelative, r->error.maxRelative);
            s.error.psnrDb = std::min(s.error.psnrDb, r->error.psnrDb);
        }
        summary.push_back(s);
    }
    results.rows.insert(results.rows.end(), summary.begin(), summary.end());
}

void markParetoFronts(BenchResults& results) {
    std::map<std::pair<std::string, std::string>, std::vector<size_t>> groups;
    for (size_t i = 0; i < results.rows.size(); ++i)
        groups[{results.rows[i].input, results.rows[i].stage}].push_back(i);
    for (const auto& [key, indices] : groups) {
        std::vector<TimeError> points;
        for (size_t i : indices) points.push_back({rankedTime(results, results.rows[i]).median, results.rows[i].error.meanRelative});
        std::vector<bool> front = paretoFront(points);
        for (size_t k = 0; k < indices.size(); ++k) results.rows[indices[k]].pareto = front[k];
    }
}

}  // namespace rmfx::accuracy
