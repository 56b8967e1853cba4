#include "run/ReplayReport.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <ctime>
#include <string_view>

#include "core/ShortNumber.h"
#include "io/file/AtomicFile.h"
#include "io/file/FileNamePart.h"
#include "io/image/ErrorHeatMap.h"
#include "io/image/ImageIO.h"
#include "io/image/RgbePacking.h"
#include "run/ReplayReportPage.h"

namespace rmfx {

namespace fs = std::filesystem;

namespace {

std::string escapeHtml(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char ch : text) {
        switch (ch) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += ch;
        }
    }
    return out;
}

std::string base64(const std::string& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                     static_cast<unsigned char>(bytes[i + 2]);
        out += {digits[v >> 18], digits[(v >> 12) & 63], digits[(v >> 6) & 63], digits[v & 63]};
    }
    if (i + 1 == bytes.size()) {
        unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
        out += {digits[v >> 18], digits[(v >> 12) & 63], '=', '='};
    } else if (i + 2 == bytes.size()) {
        unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8);
        out += {digits[v >> 18], digits[(v >> 12) & 63], digits[(v >> 6) & 63], '='};
    }
    return out;
}

// The heat map's full scale at the limits: the per-pixel limit, else the largest allowed error,
// else the percentile's or the mean's limit; nullopt without limits.
std::optional<std::pair<double, std::string>> limitScale(const ImageComparison& c) {
    if (c.pixelThreshold && *c.pixelThreshold > 0) return std::pair{*c.pixelThreshold, std::string("the per-pixel limit")};
    for (LimitCheck::Kind kind : {LimitCheck::Kind::Max, LimitCheck::Kind::Percentile, LimitCheck::Kind::Mean})
        for (const LimitCheck& check : c.checks)
            if (check.kind == kind && check.limit > 0) return std::pair{check.limit, "the " + c.checkName(check) + " limit"};
    return std::nullopt;
}

// Writes the file and returns its bytes.
Result<std::string> writeAndRead(const fs::path& file, const Image& image) {
    if (auto written = writeImage(file, image, DisplayTransform::None); !written) return Error{written.error()};
    return readWholeFile(file);
}

const char* statusWord(ReportCase::Status status) {
    switch (status) {
        case ReportCase::Status::Passed: return "passed";
        case ReportCase::Status::Failed: return "failed";
        case ReportCase::Status::Error: return "error";
    }
    return "";
}

// CSS size of a preview: small images scaled up by a whole factor to about 256 pixels wide,
// large ones shown at most 512 wide.
std::string displayStyle(int width, int height) {
    if (width <= 0 || height <= 0) return "";
    double scale = width < 256 ? std::floor(256.0 / width) : std::min(1.0, 512.0 / width);
    return "width:" + shortNumber(std::round(width * scale)) + "px;height:" + shortNumber(std::round(height * scale)) + "px";
}

// Whether a file in img/ is one the report writes: c<digits>-<anything>.js or .png.
bool isReportImageName(std::string_view name) {
    if (name.size() < 2 || name[0] != 'c' || !std::isdigit(static_cast<unsigned char>(name[1]))) return false;
    size_t afterDigits = name.find_first_not_of("0123456789", 1);
    if (afterDigits == std::string_view::npos || name[afterDigits] != '-') return false;
    std::string_view rest = name.substr(afterDigits + 1);
    return rest.ends_with(".js") || rest.ends_with(".png");
}

}  // namespace

Result<ReplayReportWriter> ReplayReportWriter::open(const fs::path& dir, std::string title) {
    std::error_code ec;
    // The images of an earlier report go; anything else a person put in img/ stays.
    if (fs::is_directory(dir / "img", ec))
        for (const fs::directory_entry& entry : fs::directory_iterator(dir / "img", ec))
            if (entry.is_regular_file(ec) && isReportImageName(entry.path().filename().string()))
                fs::remove(entry.path(), ec);
    ec.clear();
    fs::create_directories(dir / "img", ec);
    if (ec) return Error{dir.string() + ": cannot create the report's folder: " + ec.message()};
    ReplayReportWriter writer;
    writer.dir_ = dir;
    writer.title_ = std::move(title);
    return writer;
}

std::string ReplayReportWriter::link(const fs::path& file) const {
    std::error_code ec;
    fs::path relative = fs::relative(fs::absolute(file, ec), fs::absolute(dir_, ec), ec);
    return (ec || relative.empty() ? fs::absolute(file, ec) : relative).generic_string();
}

Result<ReplayReportWriter::CompareEntry> ReplayReportWriter::writeCompare(const ReportCompare& compare,
                                                                          const std::string& id, std::string& script) {
    CompareEntry entry;
    entry.label = compare.label;
    entry.id = id;
    entry.comparison = compare.comparison;
    entry.comparison.difference = Image{};
    auto embed = [&](const Image& image, const std::string& name) -> Result<void> {
        fs::path file = dir_ / "img" / (id + "-" + name + ".png");
        Result<std::string> bytes = writeAndRead(file, packRgbe(image));
        if (!bytes) return Error{bytes.error()};
        std::error_code ignored;
        fs::remove(file, ignored);  // the page reads it from the script
        script += "rmfxImages[\"" + id + "-" + name + "\"] = \"data:image/png;base64," + base64(*bytes) + "\";\n";
        return {};
    };
    if (!compare.actual.empty()) {
        if (auto done = embed(compare.actual, "actual"); !done) return Error{done.error()};
        entry.hasActual = true;
        entry.width = compare.actual.width;
        entry.height = compare.actual.height;
    }
    if (auto reference = readImage(compare.referenceFile); reference) {
        if (auto done = embed(*reference, "reference"); !done) return Error{done.error()};
        entry.hasReference = true;
        entry.referenceLink = link(compare.referenceFile);
        if (!entry.hasActual) entry.width = reference->width, entry.height = reference->height;
    }
    if (!compare.comparison.difference.empty()) {
        // Beyond the limit everything is one colour, so a larger error gets a map of its own.
        std::vector<std::pair<double, std::string>> scales;
        if (auto limit = limitScale(compare.comparison)) scales.push_back(*limit);
        double largest = compare.comparison.metrics.maxError;
        if (largest > 0 && (scales.empty() || largest > scales.front().first))
            scales.insert(scales.begin(), {largest, "the largest error"});
        if (scales.empty()) scales.push_back({1.0, "no error; full scale 1"});
        for (size_t i = 0; i < scales.size(); ++i) {
            std::string name = id + "-heat" + std::to_string(i) + ".png";
            if (auto written = writeImage(dir_ / "img" / name, errorHeatMap(compare.comparison.difference, scales[i].first),
                                          DisplayTransform::None);
                !written)
                return Error{written.error()};
            entry.heatMaps.push_back({"img/" + name, scales[i].first, scales[i].second});
        }
    }
    if (compare.actualFile) entry.actualLink = link(*compare.actualFile);
    if (compare.diffFile) entry.diffLink = link(*compare.diffFile);
    return entry;
}

Result<void> ReplayReportWriter::addCase(const ReportCase& c) {
    CaseEntry entry;
    entry.status = c.status;
    entry.name = c.name;
    entry.log = c.log;
    entry.seconds = c.seconds;
    entry.firstDifferencePass = c.firstDifferencePass;
    const std::string caseId = "c" + std::to_string(cases_.size()) + "-" + fileNamePart(c.name);
    std::string script = "window.rmfxImages = window.rmfxImages || {};\n";
    for (size_t i = 0; i < c.compares.size(); ++i) {
        auto compare = writeCompare(c.compares[i], caseId + "-" + std::to_string(i) + "-" + fileNamePart(c.compares[i].label), script);
        if (!compare) return Error{compare.error()};
        entry.compares.push_back(std::move(*compare));
    }
    if (c.firstDifference) {
        auto compare = writeCompare(*c.firstDifference, caseId + "-first-" + fileNamePart(c.firstDifference->label), script);
        if (!compare) return Error{compare.error()};
        entry.firstDifference = std::move(*compare);
    }
    fs::path scriptFile = dir_ / "img" / (caseId + ".js");
    if (auto written = writeFileAtomically(scriptFile, script, false); !written) return Error{written.error()};
    cases_.push_back(std::move(entry));
    return {};
}

namespace {

std::string canvas(const std::string& id, const std::string& style, const std::string& cls = "") {
    return "<canvas data-hdr=\"" + id + "\" style=\"" + style + "\"" + (cls.empty() ? "" : " class=\"" + cls + "\"") +
           "></canvas>";
}

}  // namespace

Result<fs::path> ReplayReportWriter::finish(double seconds) {
    int passed = 0, failed = 0, errors = 0;
    for (const CaseEntry& c : cases_)
        (c.status == ReportCase::Status::Passed ? passed : c.status == ReportCase::Status::Failed ? failed : errors)++;
    std::vector<size_t> order(cases_.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return (cases_[a].status != ReportCase::Status::Passed) > (cases_[b].status != ReportCase::Status::Passed);
    });

    std::time_t now = std::time(nullptr);
    char date[64];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));

    std::string page;
    page += "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>rmfx replay: " +
            escapeHtml(title_) + "</title>\n<style>" + replayReportStyle() + "</style>\n</head>\n<body>\n";
    page += "<header>\n<h1>rmfx replay: " + escapeHtml(title_) + "</h1>\n<p class=\"summary\">" +
            std::to_string(cases_.size()) + (cases_.size() == 1 ? " case: " : " cases: ") + std::to_string(passed) +
            " passed, " + std::to_string(failed) + " failed, " + std::to_string(errors) + " could not run; " +
            shortNumber(std::round(seconds * 100) / 100) + " s; " + date + "</p>\n";
    page += "<div class=\"controls\"><label>Exposure <input type=\"range\" id=\"ev\" min=\"-12\" max=\"12\" step=\"0.25\" "
            "value=\"0\"> <output id=\"ev-value\">0 EV</output></label><label>Tone mapping <select id=\"op\">"
            "<option value=\"clip\">clip</option><option value=\"reinhard\">Reinhard</option></select></label>"
            "<span>HDR images: linear values × 2^EV, tone-mapped, sRGB-encoded</span></div>\n</header>\n<main>\n";

    auto compareBlock = [&](const CompareEntry& e, const std::string& heading) {
        const ImageComparison& c = e.comparison;
        const bool ok = c.passed();
        std::string out = "<div class=\"compare " + std::string(ok ? "passed" : "failed") + "\" data-view=\"side\" id=\"" +
                          e.id + "\">\n<h3>" + heading + " <span class=\"badge\">" + (ok ? "ok" : "FAILED") + "</span></h3>\n";
        if (!c.problem.empty()) out += "<p class=\"problem\">" + escapeHtml(c.problem) + "</p>\n";
        if (!c.checks.empty()) {
            out += "<table class=\"metrics\"><tr><th>check</th><th>measured</th><th>limit</th><th></th></tr>\n";
            for (const LimitCheck& check : c.checks)
                out += std::string("<tr") + (check.passed() ? "" : " class=\"over\"") + "><td>" +
                       escapeHtml(c.checkName(check)) + "</td><td>" + shortNumber(check.value) + "</td><td>" +
                       shortNumber(check.limit) + "</td><td>" + (check.passed() ? "ok" : "over") + "</td></tr>\n";
            out += "</table>\n";
        }
        if (c.problem.empty())
            out += "<p class=\"where\">" + escapeHtml(c.describe()) + "</p>\n";
        const std::string style = displayStyle(e.width, e.height);
        const std::string ref = e.id + "-reference", act = e.id + "-actual";
        out += "<div class=\"view-choices\">";
        for (const auto& [value, text] : {std::pair{"side", "side by side"}, {"slider", "slider"}, {"flicker", "flicker"}})
            out += std::string("<label><input type=\"radio\" class=\"view-choice\" name=\"view-") + e.id + "\" value=\"" +
                   value + "\"" + (std::string(value) == "side" ? " checked" : "") + "> " + text + "</label> ";
        out += "</div>\n<div class=\"view side\">";
        if (e.hasReference) out += "<figure>" + canvas(ref, style) + "<figcaption>reference</figcaption></figure>";
        else out += "<figure><p class=\"problem\">no reference</p></figure>";
        if (e.hasActual) out += "<figure>" + canvas(act, style) + "<figcaption>actual</figcaption></figure>";
        if (!e.heatMaps.empty()) {
            const auto& first = e.heatMaps.front();
            out += "<figure class=\"heat-figure\"><img class=\"heat\" src=\"" + escapeHtml(first.file) + "\" style=\"" + style +
                   "\" alt=\"difference heat map\"><figcaption class=\"legend\">difference: 0 <span class=\"bar\"></span> "
                   "<span class=\"scale\">" + shortNumber(first.scale) + " (" + escapeHtml(first.meaning) +
                   ")</span> <span class=\"over\"></span> above</figcaption>";
            if (e.heatMaps.size() > 1) {
                out += "<figcaption>full scale: ";
                for (size_t i = 0; i < e.heatMaps.size(); ++i)
                    out += "<label><input type=\"radio\" class=\"heat-choice\" name=\"heat-" + e.id + "\" data-file=\"" +
                           escapeHtml(e.heatMaps[i].file) + "\" data-scale=\"" +
                           escapeHtml(shortNumber(e.heatMaps[i].scale) + " (" + e.heatMaps[i].meaning + ")") + "\"" +
                           (i == 0 ? " checked" : "") + "> " + escapeHtml(e.heatMaps[i].meaning) + "</label> ";
                out += "</figcaption>";
            }
            out += "</figure>";
        }
        out += "</div>\n";
        if (e.hasReference && e.hasActual) {
            out += "<div class=\"view slider\"><figure><div class=\"stack\">" + canvas(ref, style) + canvas(act, style, "top") +
                   "</div><figcaption>reference left of the line, actual right of it: <input type=\"range\" "
                   "class=\"split\" min=\"0\" max=\"100\" value=\"50\"></figcaption></figure></div>\n";
            out += "<div class=\"view flicker\"><figure><div class=\"stack\">" + canvas(ref, style) + canvas(act, style, "top") +
                   "</div><figcaption>showing: <span class=\"flicker-label\">actual</span></figcaption></figure></div>\n";
        }
        std::string files;
        if (!e.referenceLink.empty()) files += "<a href=\"" + escapeHtml(e.referenceLink) + "\">reference EXR</a>";
        if (!e.actualLink.empty()) files += "<a href=\"" + escapeHtml(e.actualLink) + "\">actual EXR</a>";
        if (!e.diffLink.empty()) files += "<a href=\"" + escapeHtml(e.diffLink) + "\">difference EXR</a>";
        if (!files.empty()) out += "<p class=\"files\">" + files + "</p>\n";
        return out + "</div>\n";
    };

    std::string scripts;
    for (size_t index : order) {
        const CaseEntry& c = cases_[index];
        const char* status = statusWord(c.status);
        page += "<section class=\"case " + std::string(status) + "\" data-status=\"" + status + "\" id=\"case-" +
                escapeHtml(c.name) + "\">\n<h2><span class=\"badge\">" +
                (c.status == ReportCase::Status::Passed ? "ok" : c.status == ReportCase::Status::Failed ? "FAILED" : "ERROR") +
                "</span> " + escapeHtml(c.name) + " <span class=\"time\">" + shortNumber(std::round(c.seconds * 100) / 100) +
                " s</span></h2>\n";
        if (!c.log.empty()) page += "<pre class=\"log\">" + escapeHtml(c.log) + "</pre>\n";
        if (c.firstDifference)
            page += "<div class=\"first-difference\">" +
                    compareBlock(*c.firstDifference, "first difference: pass '" + escapeHtml(c.firstDifferencePass) +
                                                         "', target '" + escapeHtml(c.firstDifference->label) + "'") +
                    "</div>\n";
        for (const CompareEntry& e : c.compares) page += compareBlock(e, escapeHtml(e.label));
        page += "</section>\n";
        scripts += "<script src=\"img/c" + std::to_string(index) + "-" + fileNamePart(c.name) + ".js\"></script>\n";
    }
    page += "</main>\n" + scripts + "<script>" + replayReportScript() + "</script>\n</body>\n</html>\n";
    fs::path index = dir_ / "index.html";
    if (auto written = writeFileAtomically(index, page, false); !written) return Error{written.error()};
    return index;
}

}  // namespace rmfx
