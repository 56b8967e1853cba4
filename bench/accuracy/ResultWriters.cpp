#include "bench/accuracy/ResultWriters.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "bench/accuracy/NumberText.h"

namespace rmfx::accuracy {
namespace {

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string jsonString(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\t': out += "\\t"; break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    char escaped[8];
                    std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
                    out += escaped;
                } else {
                    out += c;
                }
        }
    }
    return out + "\"";
}

std::string jsonNumber(double value, int significant = 9) {
    return std::isfinite(value) ? numberText(value, significant) : "null";
}

std::vector<std::string> stagesInOrder(const BenchResults& results) {
    std::vector<std::string> stages;
    for (const BenchRow& r : results.rows)
        if (std::find(stages.begin(), stages.end(), r.stage) == stages.end()) stages.push_back(r.stage);
    return stages;
}

}  // namespace

std::string resultsCsv(const BenchResults& results) {
    std::string out =
        "input,stage,variant,effects,settings,frames,median_ms,p10_ms,p90_ms,min_ms,max_ms,max_rel_error,"
        "mean_rel_error,psnr_db,pareto,wall_median_ms,wall_p10_ms,wall_p90_ms\n";
    for (const BenchRow& r : results.rows) {
        out += csvField(r.input) + "," + csvField(r.stage) + "," + csvField(r.variant) + "," + csvField(r.effects) + "," +
               csvField(r.settings) + "," + std::to_string(r.time.frames) + "," + fixedText(r.time.median, 4) + "," +
               fixedText(r.time.p10, 4) + "," + fixedText(r.time.p90, 4) + "," + fixedText(r.time.min, 4) + "," +
               fixedText(r.time.max, 4) + "," + numberText(r.error.maxRelative) + "," +
               numberText(r.error.meanRelative) + "," + fixedText(r.error.psnrDb, 3) + "," +
               (r.pareto ? "1" : "0") + "," + fixedText(r.wall.median, 4) + "," + fixedText(r.wall.p10, 4) + "," +
               fixedText(r.wall.p90, 4) + "\n";
    }
    return out;
}

std::string resultsJson(const BenchResults& results) {
    std::string out = "{\n";
    out += "  \"device\": " + jsonString(results.device) + ",\n";
    out += "  \"size\": " + jsonString(results.size) + ",\n";
    out += "  \"frames\": " + std::to_string(results.frames) + ",\n";
    out += "  \"warmup\": " + std::to_string(results.warmup) + ",\n";
    out += "  \"date\": " + jsonString(results.date) + ",\n";
    out += "  \"command\": " + jsonString(results.command) + ",\n";
    out += "  \"ranked_time\": " + jsonString(timeSourceName(results.ranked)) + ",\n";
    out += "  \"rows\": [";
    for (size_t i = 0; i < results.rows.size(); ++i) {
        const BenchRow& r = results.rows[i];
        out += std::string(i ? "," : "") + "\n    {\"input\": " + jsonString(r.input) +
               ", \"stage\": " + jsonString(r.stage) + ", \"variant\": " + jsonString(r.variant) +
               ", \"effects\": " + jsonString(r.effects) + ", \"settings\": " + jsonString(r.settings) +
               ", \"frames\": " + std::to_string(r.time.frames) + ", \"median_ms\": " + jsonNumber(r.time.median) +
               ", \"p10_ms\": " + jsonNumber(r.time.p10) + ", \"p90_ms\": " + jsonNumber(r.time.p90) +
               ", \"min_ms\": " + jsonNumber(r.time.min) + ", \"max_ms\": " + jsonNumber(r.time.max) +
               ", \"max_rel_error\": " + jsonNumber(r.error.maxRelative) +
               ", \"mean_rel_error\": " + jsonNumber(r.error.meanRelative) +
               ", \"psnr_db\": " + jsonNumber(r.error.psnrDb) + ", \"pareto\": " + (r.pareto ? "true" : "false") +
               ", \"wall_median_ms\": " + jsonNumber(r.wall.median) + ", \"wall_p10_ms\": " + jsonNumber(r.wall.p10) +
               ", \"wall_p90_ms\": " + jsonNumber(r.wall.p90) + "}";
    }
    out += "\n  ]\n}\n";
    return out;
}

std::string resultsMarkdown(const BenchResults& results, const std::string& input) {
    std::string out;
    for (const std::string& stage : stagesInOrder(results)) {
        out += "\n**" + stage + "**\n\n";
        out += std::string("| variant | settings | ") + (results.ranked == TimeSource::Gpu ? "GPU" : "wall") +
               " median ms | p10–p90 ms | max rel. error | mean rel. error | PSNR dB |\n";
        out += "| --- | --- | ---: | ---: | ---: | ---: | ---: |\n";
        for (const BenchRow& r : results.rows) {
            if (r.stage != stage || r.input != input) continue;
            std::string name = r.pareto ? "**" + r.variant + "**" : r.variant;
            const TimeSummary& t = rankedTime(results, r);
            out += "| " + name + " | " + r.settings + " | " + fixedText(t.median, 3) + " | " + fixedText(t.p10, 3) +
                   "–" + fixedText(t.p90, 3) + " | " +
                   numberText(r.error.maxRelative, 3) + " | " + numberText(r.error.meanRelative, 3) + " | " +
                   fixedText(r.error.psnrDb, 2) + " |\n";
        }
    }
    return out;
}

}  // namespace rmfx::accuracy
