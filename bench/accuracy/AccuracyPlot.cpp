#include "bench/accuracy/AccuracyPlot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "bench/accuracy/NumberText.h"

namespace rmfx::accuracy {
namespace {

constexpr double kPsnrCap = 100.0;
constexpr double kPanelWidth = 1160, kPanelHeight = 470;
constexpr double kPlotLeft = 80, kPlotRight = 600, kPlotTop = 40, kPlotBottom = 400;
constexpr double kLegendLeft = 630;
constexpr double kHeaderHeight = 76;

std::string num(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", v);
    return text;
}

std::string escaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '"') out += "&quot;";
        else out += c;
    }
    return out;
}

std::string text(double x, double y, const std::string& s, const std::string& attributes = "") {
    return "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\"" + (attributes.empty() ? "" : " " + attributes) + ">" +
           escaped(s) + "</text>\n";
}

std::string line(double x1, double y1, double x2, double y2, const std::string& style) {
    return "<line x1=\"" + num(x1) + "\" y1=\"" + num(y1) + "\" x2=\"" + num(x2) + "\" y2=\"" + num(y2) + "\" " +
           style + "/>\n";
}

// A log axis over whole decades covering [low, high] (positive).
struct LogAxis {
    double lowDecade = 0, highDecade = 1;  // log10 bounds
    double pixelLow = 0, pixelHigh = 0;    // screen positions of the bounds

    static LogAxis covering(double low, double high, double pixelLow, double pixelHigh) {
        LogAxis a;
        a.lowDecade = std::floor(std::log10(low));
        a.highDecade = std::ceil(std::log10(high));
        if (a.highDecade <= a.lowDecade) a.highDecade = a.lowDecade + 1;
        a.pixelLow = pixelLow;
        a.pixelHigh = pixelHigh;
        return a;
    }
    double low() const { return std::pow(10.0, lowDecade); }
    double high() const { return std::pow(10.0, highDecade); }
    double at(double v) const {
        double t = (std::log10(std::clamp(v, low(), high())) - lowDecade) / (highDecade - lowDecade);
        return pixelLow + t * (pixelHigh - pixelLow);
    }
    // Decades, plus 2 and 5 between them when the axis spans few decades.
    std::vector<std::pair<double, bool>> ticks() const {
        std::vector<std::pair<double, bool>> out;
        bool minor = highDecade - lowDecade <= 3;
        for (double d = lowDecade; d <= highDecade; d += 1) {
            out.push_back({std::pow(10.0, d), true});
            if (minor && d < highDecade)
                for (double m : {2.0, 5.0}) out.push_back({m * std::pow(10.0, d), true});
        }
        return out;
    }
};

std::string tickLabel(double v) {
    if (v >= 1e-3 && v < 1e4) return numberText(v, 3);
    char t[32];
    std::snprintf(t, sizeof t, "%.0e", v);
    return t;
}

std::string panel(const BenchResults& results, const std::vector<const BenchRow*>& rows, const std::string& stage,
                  double top, int inputs) {
    auto timeOf = [&](const BenchRow* r) -> const TimeSummary& { return rankedTime(results, *r); };
    std::string svg = "<g transform=\"translate(0," + num(top) + ")\">\n";
    svg += text(kPlotLeft, 24, stage + (inputs > 1 ? " (mean over " + std::to_string(inputs) + " inputs)" : ""),
                "font-size=\"16\" font-weight=\"bold\"");

    double tLow = INFINITY, tHigh = 0, eLow = INFINITY, eHigh = 0;
    for (const BenchRow* r : rows) {
        for (double t : {timeOf(r).p10, timeOf(r).p90, timeOf(r).median})
            if (t > 0 && std::isfinite(t)) tLow = std::min(tLow, t), tHigh = std::max(tHigh, t);
        double e = r->error.meanRelative;
        if (e > 0 && std::isfinite(e)) eLow = std::min(eLow, e), eHigh = std::max(eHigh, e);
    }
    if (!(tHigh > 0)) tLow = 0.1, tHigh = 1;
    if (!(eHigh > 0)) eLow = 1e-6, eHigh = 1e-5;
    LogAxis x = LogAxis::covering(tLow, tHigh, kPlotLeft, kPlotRight);
    LogAxis y = LogAxis::covering(eLow, eHigh, kPlotBottom, kPlotTop);

    svg += "<rect x=\"" + num(kPlotLeft) + "\" y=\"" + num(kPlotTop) + "\" width=\"" + num(kPlotRight - kPlotLeft) +
           "\" height=\"" + num(kPlotBottom - kPlotTop) + "\" fill=\"white\" stroke=\"black\"/>\n";
    for (auto [v, labelled] : x.ticks()) {
        double px = x.at(v);
        svg += line(px, kPlotTop, px, kPlotBottom, "stroke=\"#ddd\"");
        svg += line(px, kPlotBottom, px, kPlotBottom + 5, "stroke=\"black\"");
        svg += text(px, kPlotBottom + 18, tickLabel(v), "font-size=\"11\" text-anchor=\"middle\"");
    }
    for (auto [v, labelled] : y.ticks()) {
        double py = y.at(v);
        svg += line(kPlotLeft, py, kPlotRight, py, "stroke=\"#ddd\"");
        svg += line(kPlotLeft - 5, py, kPlotLeft, py, "stroke=\"black\"");
        svg += text(kPlotLeft - 8, py + 4, tickLabel(v), "font-size=\"11\" text-anchor=\"end\"");
    }
    svg += text((kPlotLeft + kPlotRight) / 2, kPlotBottom + 40, std::string(timeSourceTitle(results.ranked)) + " (log scale)",
                "font-size=\"13\" text-anchor=\"middle\"");
    svg += "<text font-size=\"13\" text-anchor=\"middle\" transform=\"translate(22," + num((kPlotTop + kPlotBottom) / 2) +
           ") rotate(-90)\">mean relative luminance error (log scale)</text>\n";

    // The front as a step line: right from each point at its error, then down to the next.
    std::vector<const BenchRow*> front;
    for (const BenchRow* r : rows)
        if (r->pareto) front.push_back(r);
    std::sort(front.begin(), front.end(), [&](const BenchRow* a, const BenchRow* b) {
        return timeOf(a).median < timeOf(b).median ||
               (timeOf(a).median == timeOf(b).median && a->error.meanRelative > b->error.meanRelative);
    });
    if (!front.empty()) {
        std::string points;
        for (size_t i = 0; i < front.size(); ++i) {
            double px = x.at(timeOf(front[i]).median), py = y.at(front[i]->error.meanRelative);
            if (i > 0) points += num(px) + "," + num(y.at(front[i - 1]->error.meanRelative)) + " ";
            points += num(px) + "," + num(py) + " ";
        }
        svg += "<polyline points=\"" + points + "\" fill=\"none\" stroke=\"#c03020\" stroke-width=\"1.5\"/>\n";
    }

    bool clipped = false, capped = false;
    for (size_t i = 0; i < rows.size(); ++i) {
        const BenchRow& r = *rows[i];
        double e = r.error.meanRelative;
        clipped = clipped || !(e > 0) || !std::isfinite(e);
        double py = y.at(std::isfinite(e) ? e : y.high());
        svg += line(x.at(timeOf(&r).p10), py, x.at(timeOf(&r).p90), py, "stroke=\"#5070b0\" stroke-width=\"2\"");
        double px = x.at(timeOf(&r).median);
        svg += "<circle cx=\"" + num(px) + "\" cy=\"" + num(py) + "\" r=\"4.5\" stroke=\"" +
               std::string(r.pareto ? "#c03020" : "#203060") + "\" fill=\"" + (r.pareto ? "#c03020" : "white") +
               "\" stroke-width=\"1.5\"/>\n";
        svg += text(px + 6, py - 5, std::to_string(i + 1), "font-size=\"11\"");

        double psnr = r.error.psnrDb;
        capped = capped || psnr > kPsnrCap;
        std::string psnrText = psnr > kPsnrCap ? "≥100 dB" : fixedText(psnr, 1) + " dB";
        svg += text(kLegendLeft, kPlotTop + 4 + 13.5 * static_cast<double>(i),
                    std::to_string(i + 1) + "  " + r.variant + "  (" + psnrText + ")",
                    std::string("font-size=\"11\"") + (r.pareto ? " font-weight=\"bold\" fill=\"#c03020\"" : ""));
    }
    std::string note = "filled red: Pareto front (no variant both faster and more accurate); bar: p10–p90 time";
    svg += text(kPlotLeft, kPlotBottom + 58, note, "font-size=\"11\" fill=\"#444\"");
    std::string notes;
    if (capped) notes += "PSNR above 100 dB (inf: identical 8-bit images) shown as ≥100 dB. ";
    if (clipped) notes += "Errors of 0 (or not finite) drawn at the bottom (top) edge.";
    if (!notes.empty()) svg += text(kPlotLeft, kPlotBottom + 72, notes, "font-size=\"11\" fill=\"#444\"");
    svg += "</g>\n";
    return svg;
}

}  // namespace

std::string accuracyPlotSvg(const BenchResults& results, const std::string& input) {
    std::vector<std::string> stages;
    std::vector<std::string> inputs;
    for (const BenchRow& r : results.rows) {
        if (r.input != kAllInputs && std::find(inputs.begin(), inputs.end(), r.input) == inputs.end())
            inputs.push_back(r.input);
        if (r.input == input && std::find(stages.begin(), stages.end(), r.stage) == stages.end())
            stages.push_back(r.stage);
    }
    double height = kHeaderHeight + kPanelHeight * static_cast<double>(std::max<size_t>(stages.size(), 1));
    std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                      num(kPanelWidth) + "\" height=\"" + num(height) + "\" viewBox=\"0 0 " + num(kPanelWidth) + " " +
                      num(height) + "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n";
    svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    svg += text(20, 24, "rmfx bench: error against time per variant", "font-size=\"18\" font-weight=\"bold\"");
    svg += text(20, 44, results.device, "font-size=\"12\" fill=\"#444\"");
    svg += text(20, 60,
                "inputs " + results.size + " · " + timeSourceName(results.ranked) + " time, median of " +
                    std::to_string(results.frames) + " frames after " + std::to_string(results.warmup) + " warm-up · " +
                    results.date,
                "font-size=\"12\" fill=\"#444\"");
    int inputCount = input == kAllInputs ? static_cast<int>(inputs.size()) : 1;
    for (size_t s = 0; s < stages.size(); ++s) {
        std::vector<const BenchRow*> rows;
        for (const BenchRow& r : results.rows)
            if (r.stage == stages[s] && r.input == input) rows.push_back(&r);
        svg += panel(results, rows, stages[s], kHeaderHeight + kPanelHeight * static_cast<double>(s), inputCount);
    }
    svg += "</svg>\n";
    return svg;
}

}  // namespace rmfx::accuracy
