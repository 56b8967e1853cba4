#include <algorithm>
#include <cmath>
#include <string>

#include "core/ShortNumber.h"
#include "io/image/ImageCompare.h"

namespace rmfx {

namespace {

// What the error of a metric is called in messages.
const char* errorWord(ErrorMetric metric) {
    return metric == ErrorMetric::Relative ? "relative error" : metric == ErrorMetric::Itp ? "ΔE_ITP" : "error";
}

// "99th", "99.9th", "1st", "2nd", "3rd", "11th": the percentile in words.
std::string ordinal(double n) {
    std::string text = shortNumber(n);
    if (n != std::floor(n)) return text + "th";
    long long whole = static_cast<long long>(n);
    if (whole % 100 >= 11 && whole % 100 <= 13) return text + "th";
    switch (whole % 10) {
        case 1: return text + "st";
        case 2: return text + "nd";
        case 3: return text + "rd";
        default: return text + "th";
    }
}

}  // namespace

bool ImageComparison::passed() const {
    return problem.empty() && std::all_of(checks.begin(), checks.end(), [](const LimitCheck& c) { return c.passed(); });
}

std::string ImageComparison::checkName(const LimitCheck& check) const {
    const std::string error = errorWord(metric);
    switch (check.kind) {
        case LimitCheck::Kind::Max: return "max " + error;
        case LimitCheck::Kind::Mean: return "mean " + error;
        case LimitCheck::Kind::Percentile: return ordinal(percentile.value_or(100.0)) + " percentile " + error;
        case LimitCheck::Kind::FailFraction:
            return "fail fraction (pixels with " + error + " > " + shortNumber(pixelThreshold.value_or(0.0)) + ")";
    }
    return error;
}

std::string ImageComparison::describe() const {
    const std::string error = errorWord(metric) + std::string(" ");
    std::string out = problem;
    auto clause = [&](const std::string& text) { out += (out.empty() ? "" : "; ") + text; };
    auto compared = [](const LimitCheck& c) {
        return shortNumber(c.value) + (c.passed() ? " ≤ " : " > ") + shortNumber(c.limit);
    };
    std::string where;
    if (metrics.maxError > 0) {
        where = " at x=" + std::to_string(metrics.maxX) + " y=" + std::to_string(metrics.maxY);
        if (metric != ErrorMetric::Itp) where += " channel " + std::to_string(metrics.maxChannel);
    }
    if (checks.empty() && difference.empty()) return out;
    if (checks.empty()) {
        clause("max " + error + shortNumber(metrics.maxError) + where + ", mean " + error + shortNumber(metrics.meanError));
        return out;
    }
    for (const LimitCheck& c : checks) {
        switch (c.kind) {
            case LimitCheck::Kind::Max: clause(checkName(c) + " " + compared(c) + where); break;
            case LimitCheck::Kind::Mean:
            case LimitCheck::Kind::Percentile: clause(checkName(c) + " " + compared(c)); break;
            case LimitCheck::Kind::FailFraction:
                clause("fail fraction " + compared(c) + " (" + std::to_string(metrics.failingPixels) + " of " +
                       std::to_string(metrics.pixelCount) + " pixels with " + error + "> " +
                       shortNumber(pixelThreshold.value_or(0.0)) + ")");
                break;
        }
    }
    return out;
}

}  // namespace rmfx
