#include "frontend/replay/ReplayManifest.h"

#include "model/EffectSelection.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>

#include "io/xml/XmlDocumentParser.h"
#include "io/xml/XmlElementReader.h"

namespace rmfx {

namespace fs = std::filesystem;

namespace {

using xml::ElementReader;
using xml::XMLElement;

constexpr int kMaxFrames = 1000000;
constexpr double kDefaultFloor = 1e-3;

// Attributes that <defaults> gives every case and compare that does not set them itself.
struct RunAttributes {
    std::optional<std::pair<int, int>> size;
    std::optional<int> frames;
    std::optional<float> dt;
};

struct LimitAttributes {
    std::optional<ErrorMetric> metric;
    std::optional<double> floor, luminance, max, mean, percentile, percentileMax, pixel, failFraction;
    bool percentileWritten = false, percentileMaxWritten = false;  // valid or not
    std::optional<bool> half;
};

constexpr std::initializer_list<const char*> kCaseAttributes = {"name", "workspace", "size", "frames", "dt", "effects", "check"};
constexpr std::initializer_list<const char*> kCompareAttributes = {
    "target", "reference", "error", "floor", "luminance", "max", "mean", "percentile", "percentile-max", "pixel",
    "fail-fraction", "store"};
constexpr std::initializer_list<const char*> kDefaultsAttributes = {
    "size", "frames", "dt", "error", "floor", "luminance", "max", "mean", "percentile", "percentile-max", "pixel",
    "fail-fraction", "store"};

// Case names become folder names in the output: no separators, no leading dot.
bool validCaseName(const std::string& name) {
    if (name.empty() || name[0] == '.' || name[0] == '-') return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
    });
}

bool isExr(const fs::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".exr";
}

// A number attribute within [low, high], or (low, high] (high: none when infinite).
std::optional<double> bounded(const ElementReader& r, const char* name, double low, std::optional<double> high,
                              bool lowIncluded = true) {
    auto v = r.number(name);
    if (!v) return std::nullopt;
    bool ok = (lowIncluded ? *v >= low : *v > low) && (!high || *v <= *high);
    if (!ok) {
        char text[96];
        if (high)
            std::snprintf(text, sizeof text, lowIncluded ? "must lie in [%g, %g]" : "must lie in (%g, %g]", low, *high);
        else
            std::snprintf(text, sizeof text, lowIncluded ? "must be ≥ %g" : "must be greater than %g", low);
        r.error("attribute '" + std::string(name) + "' " + text + ", got '" + r.raw(name) + "'");
        return std::nullopt;
    }
    return *v;
}

class ManifestParser {
public:
    ManifestParser(std::string file, fs::path folder, Diagnostics& diagnostics)
        : file_(std::move(file)), folder_(std::move(folder)), diagnostics_(diagnostics) {}

    void parse(const XMLElement* root, ReplayManifest& manifest) {
        ElementReader r(root, file_, diagnostics_, {"version", "sandbox"});
        auto version = r.string("version", true);
        if (version && *version != "1") r.error("unsupported version '" + *version + "': this rmfx reads version 1");
        manifest.media.sandbox = r.boolean("sandbox").value_or(true);
        // <defaults> applies to every case, wherever it stands.
        const XMLElement* defaults = nullptr;
        for (const XMLElement* e = root->FirstChildElement("defaults"); e; e = e->NextSiblingElement("defaults")) {
            if (defaults) {
                ElementReader(e, file_, diagnostics_, kDefaultsAttributes)
                    .error("a second <defaults> (the first is at line " + std::to_string(defaults->GetLineNum()) +
                           "): a manifest has one");
                continue;
            }
            defaults = e;
            ElementReader d(e, file_, diagnostics_, kDefaultsAttributes);
            defaultRun_ = readRun(d);
            defaultLimits_ = readLimits(d);
            xml::noChildren(e, file_, diagnostics_);
        }
        for (const XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
            std::string_view tag = e->Name();
            if (tag == "defaults") continue;
            if (tag == "media") {
                parseMedia(e, manifest);
                continue;
            }
            if (tag != "case") {
                xml::errorAt(e, file_, diagnostics_,
                             "unknown element <" + std::string(tag) + "> in <replay> (expected defaults, media, case)");
                continue;
            }
            if (auto c = parseCase(e, manifest)) manifest.cases.push_back(std::move(*c));
        }
        if (manifest.cases.empty() && !hasErrors(diagnostics_)) r.error("no <case>: nothing to replay");
    }

private:
    RunAttributes readRun(const ElementReader& r) {
        RunAttributes run;
        run.size = r.size("size", "128x128");
        run.frames = r.integer("frames", 1);
        if (run.frames && *run.frames > kMaxFrames) {
            r.error("attribute 'frames': expected a count from 1 to " + std::to_string(kMaxFrames) + ", got '" +
                    r.raw("frames") + "'");
            run.frames.reset();
        }
        if (auto dt = bounded(r, "dt", 0.0, std::nullopt)) run.dt = static_cast<float>(*dt);
        return run;
    }

    LimitAttributes readLimits(const ElementReader& r) {
        LimitAttributes l;
        l.metric = r.choice<ErrorMetric>(
            "error", {{"absolute", ErrorMetric::Absolute}, {"relative", ErrorMetric::Relative}, {"itp", ErrorMetric::Itp}});
        l.floor = bounded(r, "floor", 0.0, std::nullopt, false);
        l.luminance = bounded(r, "luminance", 0.0, std::nullopt, false);
        l.max = bounded(r, "max", 0.0, std::nullopt);
        l.mean = bounded(r, "mean", 0.0, std::nullopt);
        l.percentile = bounded(r, "percentile", 0.0, 100.0, false);
        l.percentileMax = bounded(r, "percentile-max", 0.0, std::nullopt);
        l.percentileWritten = r.has("percentile");
        l.percentileMaxWritten = r.has("percentile-max");
        l.pixel = bounded(r, "pixel", 0.0, std::nullopt);
        l.failFraction = bounded(r, "fail-fraction", 0.0, 1.0);
        l.half = r.choice<bool>("store", {{"float", false}, {"half", true}});
        return l;
    }

    std::optional<ReplayCase> parseCase(const XMLElement* e, const ReplayManifest& manifest) {
        ElementReader r(e, file_, diagnostics_, kCaseAttributes);
        ReplayCase c;
        c.where = r.where();
        c.name = r.string("name", true).value_or("");
        bool named = r.has("name");
        if (named && !validCaseName(c.name)) {
            r.error("attribute 'name': '" + c.name +
                    "' is not a valid case name (letters, digits, '_', '-' and '.', not starting with '.' or '-': it "
                    "names a folder of the output)");
            named = false;
        } else if (const ReplayCase* first = named ? manifest.findCase(c.name) : nullptr) {
            r.error("case '" + c.name + "' is already defined at line " + std::to_string(first->where.line));
            named = false;
        }
        auto workspace = r.string("workspace", true);
        if (auto effects = r.string("effects")) c.effects = splitNameList(*effects);
        c.check = r.boolean("check").value_or(false);
        RunAttributes run = readRun(r);
        if (auto size = run.size ? run.size : defaultRun_.size) c.run.size = {size->first, size->second};
        c.run.frames = run.frames.value_or(defaultRun_.frames.value_or(1));
        c.run.deltaTime = run.dt.value_or(defaultRun_.dt.value_or(1.0f / 60.0f));
        for (const XMLElement* child = e->FirstChildElement(); child; child = child->NextSiblingElement()) {
            std::string_view tag = child->Name();
            if (tag == "set") {
                parseSet(child, c);
            } else if (tag == "input") {
                parseInput(child, c);
            } else if (tag == "compare") {
                parseCompare(child, c);
            } else {
                xml::errorAt(child, file_, diagnostics_,
                             "unknown element <" + std::string(tag) + "> in " + r.label() + " (expected set, input, compare)");
            }
        }
        if (c.compares.empty() && !e->FirstChildElement("compare")) r.error("no <compare>: the case checks nothing");
        if (!named || !workspace) return std::nullopt;
        c.workspaceText = *workspace;
        c.workspace = (folder_ / *workspace).lexically_normal();
        return c;
    }

    // <media dir="…"/>: a folder of every case's media search path, which the sandbox also allows.
    void parseMedia(const XMLElement* e, ReplayManifest& manifest) {
        ElementReader r(e, file_, diagnostics_, {"dir"});
        auto dir = r.string("dir", true);
        xml::noChildren(e, file_, diagnostics_);
        if (!dir) return;
        fs::path folder = (folder_ / *dir).lexically_normal();
        std::error_code error;
        if (!fs::is_directory(folder, error)) return r.error("media folder '" + *dir + "' is not a folder (looked for " + folder.string() + ")");
        manifest.media.searchPath.push_back(folder);
    }

    void parseSet(const XMLElement* e, ReplayCase& c) {
        ElementReader r(e, file_, diagnostics_, {"name", "value"});
        auto name = r.string("name", true);
        auto value = r.string("value", true);
        xml::noChildren(e, file_, diagnostics_);
        if (!name || !value) return;
        for (const ReplaySet& other : c.sets)
            if (other.name == *name) {
                r.error("variable '" + *name + "' is already set at line " + std::to_string(other.where.line));
                return;
            }
        c.sets.push_back({r.where(), *name, *value});
    }

    void parseInput(const XMLElement* e, ReplayCase& c) {
        ElementReader r(e, file_, diagnostics_, {"name", "file"});
        auto name = r.identifier("name", false);
        auto file = r.string("file", true);
        xml::noChildren(e, file_, diagnostics_);
        if (!file) return;
        for (const ReplayInput& other : c.inputs)
            if (other.name == name.value_or("")) {
                r.error((other.name.empty() ? std::string("the input") : "input '" + other.name + "'") +
                        " is already given at line " + std::to_string(other.where.line));
                return;
            }
        c.inputs.push_back({r.where(), name.value_or(""), *file, (folder_ / *file).lexically_normal()});
    }

    void parseCompare(const XMLElement* e, ReplayCase& c) {
        ElementReader r(e, file_, diagnostics_, kCompareAttributes);
        ReplayCompare m;
        m.where = r.where();
        auto target = r.identifier("target", false);
        auto reference = r.string("reference", true);
        if (reference && !isExr(*reference)) {
            r.error("attribute 'reference': '" + *reference +
                    "' is not an OpenEXR file: references are .exr files, which keep the render's float values");
            reference.reset();
        }
        LimitAttributes own = readLimits(r);
        xml::noChildren(e, file_, diagnostics_);

        CompareLimits& l = m.limits;
        l.metric = own.metric.value_or(defaultLimits_.metric.value_or(ErrorMetric::Absolute));
        if (own.floor && l.metric != ErrorMetric::Relative) r.error("attribute 'floor' applies to error=\"relative\"");
        l.floor = own.floor.value_or(defaultLimits_.floor.value_or(kDefaultFloor));
        if (own.luminance && l.metric != ErrorMetric::Itp) r.error("attribute 'luminance' applies to error=\"itp\"");
        l.luminance = own.luminance.value_or(defaultLimits_.luminance.value_or(kItpDefaultLuminance));
        l.max = own.max ? own.max : defaultLimits_.max;
        l.mean = own.mean ? own.mean : defaultLimits_.mean;
        readPercentile(r, own, l);
        l.pixel = own.pixel ? own.pixel : defaultLimits_.pixel;
        auto failFraction = own.failFraction ? own.failFraction : defaultLimits_.failFraction;
        if (failFraction && !l.pixel)
            r.error("'fail-fraction' needs a 'pixel' threshold (on the <compare> or in <defaults>)");
        l.failFraction = failFraction.value_or(0.0);
        if (!l.max && !l.mean && !l.percentile && !l.pixel) l.max = 0.0;  // no limit at all: the images must be equal
        m.storeHalf = own.half.value_or(defaultLimits_.half.value_or(false));

        if (!reference || (r.has("target") && !target)) return;
        m.target = target.value_or("");
        m.referenceText = *reference;
        m.reference = (folder_ / *reference).lexically_normal();
        for (const ReplayCompare& other : c.compares)
            if (other.label() == m.label()) {
                r.error("a second <compare> of '" + m.label() + "' in case '" + (c.name.empty() ? "?" : c.name) +
                        "' (the first is at line " + std::to_string(other.where.line) + ")");
                return;
            }
        if (auto [first, inserted] = references_.try_emplace(m.reference.string(), m.where.line); !inserted) {
            r.error("reference '" + *reference + "' is already the reference of the <compare> at line " +
                    std::to_string(first->second) + ": --update would write one over the other");
            return;
        }
        c.compares.push_back(std::move(m));
    }

    // percentile="99" percentile-max="1": one limit from two attributes, each of which may come
    // from <defaults>. A percentile in <defaults> alone limits nothing: it says which percentile
    // the compares that give a percentile-max mean.
    void readPercentile(const ElementReader& r, const LimitAttributes& own, CompareLimits& l) {
        auto percentile = own.percentile ? own.percentile : defaultLimits_.percentile;
        auto max = own.percentileMax ? own.percentileMax : defaultLimits_.percentileMax;
        bool percentileWritten = own.percentileWritten || defaultLimits_.percentileWritten;
        bool maxWritten = own.percentileMaxWritten || defaultLimits_.percentileMaxWritten;
        if (own.percentileWritten && !maxWritten)
            r.error("'percentile' needs a 'percentile-max' limit (on the <compare> or in <defaults>)");
        if (maxWritten && !percentileWritten)
            r.error("'percentile-max' needs a 'percentile' (on the <compare> or in <defaults>)");
        if (percentile && max) l.percentile = PercentileLimit{*percentile, *max};
    }

    std::string file_;
    fs::path folder_;
    Diagnostics& diagnostics_;
    RunAttributes defaultRun_;
    LimitAttributes defaultLimits_;
    std::map<std::string, int> references_;  // resolved reference path → line of its <compare>
};

}  // namespace

std::vector<std::pair<std::string, std::string>> ReplayCase::overrides() const {
    std::vector<std::pair<std::string, std::string>> out;
    for (const ReplaySet& s : sets) out.emplace_back(s.name, s.value);
    return out;
}

std::string ReplayInput::label() const {
    return "<input " + (name.empty() ? std::string() : "name=\"" + name + "\" ") + "file=\"" + fileText + "\">";
}

const ReplayCase* ReplayManifest::findCase(std::string_view name) const {
    for (const ReplayCase& c : cases)
        if (c.name == name) return &c;
    return nullptr;
}

Result<ReplayManifest> parseReplayManifestText(const std::string& text, const fs::path& path, const fs::path& folder) {
    std::string file = path.string();
    return xml::parseXmlText(text, file, "replay", [&](const XMLElement* root, Diagnostics& diagnostics) {
        ReplayManifest manifest;
        manifest.path = path;
        manifest.folder = folder;
        ManifestParser(file, folder, diagnostics).parse(root, manifest);
        // <defaults> is read before the cases wherever it stands: report in line order.
        std::stable_sort(diagnostics.begin(), diagnostics.end(),
                         [](const Diagnostic& a, const Diagnostic& b) { return a.where.line < b.where.line; });
        return manifest;
    });
}

Result<ReplayManifest> parseReplayManifestFile(const fs::path& path) {
    return xml::parseXmlFile(path, [&](const std::string& text) { return parseReplayManifestText(text, path, xml::folderOf(path)); });
}

}  // namespace rmfx
