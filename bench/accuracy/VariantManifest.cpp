#include "bench/accuracy/VariantManifest.h"

#include <algorithm>
#include <cassert>
#include <set>
#include <sstream>

#include "io/xml/XmlDocumentParser.h"
#include "io/xml/XmlElementReader.h"

namespace rmfx::accuracy {

namespace fs = std::filesystem;

namespace {

using xml::ElementReader;
using xml::XMLElement;

std::vector<std::string> words(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

std::string joined(const std::vector<std::string>& list, const char* separator = " ") {
    std::string out;
    for (const std::string& s : list) out += (out.empty() ? "" : separator) + s;
    return out;
}

// "a b c" → {a, b, c}; "0 1, 0.05 0.95" → {"0 1", "0.05 0.95"}: commas separate the items when
// there is one, else white space does.
std::vector<std::string> items(const std::string& text) {
    if (text.find(',') == std::string::npos) return words(text);
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string item; std::getline(in, item, ',');) out.push_back(joined(words(item)));
    return out;
}

class Parser {
public:
    Parser(std::string file, fs::path folder, Diagnostics& diagnostics)
        : file_(std::move(file)), folder_(std::move(folder)), diagnostics_(diagnostics) {}

    void parse(const XMLElement* root, VariantManifest& manifest) {
        ElementReader rootReader(root, file_, diagnostics_, {});
        std::set<std::string> sceneNames, stageNames;
        int stageElements = 0;
        for (const XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
            std::string tag = e->Name();
            if (tag == "scene") {
                if (auto scene = parseScene(e)) {
                    if (!sceneNames.insert(scene->name).second)
                        ElementReader(e, file_, diagnostics_, {"name", "file", "workspace", "target"})
                            .error("a second scene named '" + scene->name + "'");
                    manifest.scenes.push_back(std::move(*scene));
                }
            } else if (tag == "stage") {
                ++stageElements;
                if (auto stage = parseStage(e)) {
                    if (!stageNames.insert(stage->name).second)
                        xml::errorAt(e, file_, diagnostics_, "a second <stage name=\"" + stage->name + "\">");
                    manifest.stages.push_back(std::move(*stage));
                }
            } else {
                xml::errorAt(e, file_, diagnostics_,
                             "unknown element <" + tag + "> in <bench-variants> (expected <scene> or <stage>)");
            }
        }
        if (stageElements == 0) rootReader.error("no <stage>: the manifest names nothing to measure");
    }

private:
    std::optional<SceneSpec> parseScene(const XMLElement* e) {
        ElementReader r(e, file_, diagnostics_, {"name", "file", "workspace", "target"});
        xml::noChildren(e, file_, diagnostics_);
        SceneSpec s;
        s.where = r.where();
        auto name = r.identifier("name");
        auto file = r.string("file");
        auto workspace = r.string("workspace");
        auto target = r.string("target");
        if (!name) return std::nullopt;
        s.name = *name;
        if (file.has_value() == workspace.has_value()) {
            r.error("give either file=\"IMAGE.exr\" or workspace=\"WORKSPACE.xml\" with target=\"TARGET\"");
            return std::nullopt;
        }
        if (file) {
            if (target) r.error("attribute 'target' goes with workspace=, not with file=");
            s.file = folder_ / *file;
        } else {
            if (!target) {
                r.error("missing attribute 'target' (the render target of the workspace to use as the input)");
                return std::nullopt;
            }
            s.workspace = folder_ / *workspace;
            s.target = *target;
        }
        return s;
    }

    std::optional<StageSpec> parseStage(const XMLElement* e) {
        ElementReader r(e, file_, diagnostics_, {"name", "workspace", "ideal", "output"});
        StageSpec s;
        s.where = r.where();
        auto name = r.identifier("name");
        auto workspace = r.string("workspace", true);
        auto ideal = r.choice<IdealKind>("ideal", {{"bloom", IdealKind::Bloom},
                                                   {"streak", IdealKind::Streak},
                                                   {"luminance", IdealKind::Luminance},
                                                   {"tonemap", IdealKind::ToneMap}});
        if (!r.has("ideal")) r.error("missing attribute 'ideal' (bloom, streak, luminance or tonemap)");
        auto output = r.identifier("output");
        size_t before = diagnostics_.size();
        for (const XMLElement* a = e->FirstChildElement(); a; a = a->NextSiblingElement()) {
            if (std::string(a->Name()) != "axis") {
                xml::errorAt(a, file_, diagnostics_,
                             "unknown element <" + std::string(a->Name()) + "> in <stage> (expected <axis>)");
                continue;
            }
            if (auto axis = parseAxis(a)) s.axes.push_back(std::move(*axis));
        }
        if (!name || !workspace || !ideal || !output || diagnostics_.size() != before) return std::nullopt;
        s.name = *name;
        s.workspace = folder_ / *workspace;
        s.ideal = *ideal;
        s.output = *output;
        checkAxes(r, s);
        return s;
    }

    void checkAxes(const ElementReader& r, const StageSpec& s) {
        int effectAxes = 0;
        std::set<std::string> variables;
        for (const VariantAxis& a : s.axes) {
            effectAxes += a.effects ? 1 : 0;
            for (const std::string& v : a.variables)
                if (!variables.insert(v).second) r.error("variable '" + v + "' is set by two <axis> elements");
        }
        if (effectAxes != 1)
            r.error("needs exactly one <axis effects=\"…\"> (the stage's algorithms), found " + std::to_string(effectAxes));
        if (effectAxes != 1) return;
        const VariantAxis& effects = s.effectsAxis();
        for (const VariantAxis& a : s.axes) {
            if (a.with.empty()) continue;
            bool known = std::any_of(effects.values.begin(), effects.values.end(),
                                     [&](const AxisValue& v) { return v.words[0] == a.with; });
            if (!known)
                diagnostics_.push_back({Diagnostic::Severity::Error, a.where, "<axis name=\"" + a.name + "\">",
                                        "attribute 'with': '" + a.with + "' is not one of the stage's effects (" +
                                            joined(effectNames(effects), ", ") + ")"});
        }
    }

    static std::vector<std::string> effectNames(const VariantAxis& effects) {
        std::vector<std::string> out;
        for (const AxisValue& v : effects.values) out.push_back(v.words[0]);
        return out;
    }

    std::optional<VariantAxis> parseAxis(const XMLElement* e) {
        ElementReader r(e, file_, diagnostics_,
                        {"name", "effects", "variable", "variables", "values", "labels", "default", "crossed", "with"});
        xml::noChildren(e, file_, diagnostics_);
        VariantAxis a;
        a.where = r.where();
        int kinds = (r.has("effects") ? 1 : 0) + (r.has("variable") ? 1 : 0) + (r.has("variables") ? 1 : 0);
        if (kinds != 1) {
            r.error("give one of effects=\"A B\", variable=\"NAME\" with values=, or variables=\"A B\" with values=");
            return std::nullopt;
        }
        auto crossed = r.has("crossed") ? r.boolean("crossed") : std::optional<bool>(false);
        auto defaultText = r.string("default", true);
        std::vector<std::string> valueItems;
        if (r.has("effects")) {
            a.effects = true;
            a.name = r.string("name").value_or("effects");
            if (r.has("values") || r.has("with")) r.error("an effects axis lists its values in effects= and takes no with=");
            valueItems = words(*r.string("effects"));
        } else {
            a.variables = words(*r.string(r.has("variable") ? "variable" : "variables"));
            if (a.variables.empty()) {
                r.error("names no variable");
                return std::nullopt;
            }
            if (r.has("variable") && a.variables.size() != 1)
                r.error("variable= names one variable; use variables=\"A B\" for several set together");
            a.name = r.string("name").value_or(joined(a.variables, "/"));
            a.with = r.string("with").value_or("");
            auto values = r.string("values", true);
            if (!values) return std::nullopt;
            valueItems = items(*values);
        }
        if (valueItems.empty()) {
            r.error("lists no values");
            return std::nullopt;
        }
        std::vector<std::string> labels = r.has("labels") ? items(*r.string("labels")) : valueItems;
        if (labels.size() != valueItems.size()) {
            r.error("attribute 'labels': " + std::to_string(labels.size()) + " labels for " +
                    std::to_string(valueItems.size()) + " values");
            return std::nullopt;
        }
        size_t wordsPerValue = a.effects ? 1 : a.variables.size();
        std::set<std::string> seen;
        for (size_t i = 0; i < valueItems.size(); ++i) {
            AxisValue v{labels[i], words(valueItems[i])};
            if (v.words.size() != wordsPerValue) {
                r.error("value '" + valueItems[i] + "' has " + std::to_string(v.words.size()) + " words for " +
                        std::to_string(wordsPerValue) + " variables (" + joined(a.variables) +
                        "); separate values by commas");
                return std::nullopt;
            }
            if (!seen.insert(joined(v.words)).second) r.error("value '" + valueItems[i] + "' is listed twice");
            a.values.push_back(std::move(v));
        }
        if (!crossed || !defaultText) return std::nullopt;
        a.crossed = *crossed;
        std::string wanted = joined(words(*defaultText));
        auto found = std::find_if(a.values.begin(), a.values.end(),
                                  [&](const AxisValue& v) { return joined(v.words) == wanted || v.label == *defaultText; });
        if (found == a.values.end()) {
            r.error("attribute 'default': '" + *defaultText + "' is not one of its values");
            return std::nullopt;
        }
        a.defaultIndex = static_cast<size_t>(found - a.values.begin());
        return a;
    }

    std::string file_;
    fs::path folder_;
    Diagnostics& diagnostics_;
};

}  // namespace

const char* idealKindName(IdealKind kind) {
    switch (kind) {
        case IdealKind::Bloom: return "bloom";
        case IdealKind::Streak: return "streak";
        case IdealKind::Luminance: return "luminance";
        case IdealKind::ToneMap: return "tonemap";
    }
    return "?";
}

const VariantAxis& StageSpec::effectsAxis() const {
    auto it = std::find_if(axes.begin(), axes.end(), [](const VariantAxis& a) { return a.effects; });
    assert(it != axes.end());
    return *it;
}

const StageSpec* VariantManifest::findStage(const std::string& name) const {
    for (const StageSpec& s : stages)
        if (s.name == name) return &s;
    return nullptr;
}

Result<VariantManifest> parseVariantManifestText(const std::string& text, const fs::path& path) {
    return xml::parseXmlText(text, path.string(), "bench-variants", [&](const XMLElement* root, Diagnostics& diagnostics) {
        VariantManifest manifest;
        manifest.path = path;
        Parser(path.string(), path.parent_path(), diagnostics).parse(root, manifest);
        return manifest;
    });
}

Result<VariantManifest> parseVariantManifestFile(const fs::path& path) {
    return xml::parseXmlFile(path, [&](const std::string& text) { return parseVariantManifestText(text, path); });
}

std::string Variant::settingsText() const {
    std::string out;
    for (const auto& [name, value] : settings) out += (out.empty() ? "" : " ") + name + "=" + value;
    return out;
}

std::vector<Variant> expandVariants(const StageSpec& stage) {
    const size_t n = stage.axes.size();
    size_t effectsIndex = 0;
    while (effectsIndex < n && !stage.axes[effectsIndex].effects) ++effectsIndex;
    assert(effectsIndex < n);

    std::vector<Variant> out;
    std::set<std::vector<size_t>> seen;
    auto add = [&](const std::vector<size_t>& choice) {
        if (!seen.insert(choice).second) return;
        Variant v;
        const VariantAxis& effects = stage.axes[effectsIndex];
        v.effect = effects.values[choice[effectsIndex]].words[0];
        v.name = v.effect;
        for (size_t i = 0; i < n; ++i) {
            const VariantAxis& a = stage.axes[i];
            if (a.effects) continue;
            const AxisValue& value = a.values[choice[i]];
            for (size_t k = 0; k < a.variables.size(); ++k) v.settings.emplace_back(a.variables[k], value.words[k]);
            if (a.crossed || choice[i] != a.defaultIndex) v.name += " " + a.name + "=" + value.label;
        }
        out.push_back(std::move(v));
    };

    std::vector<size_t> defaults(n);
    for (size_t i = 0; i < n; ++i) defaults[i] = stage.axes[i].defaultIndex;

    // The cross product of the crossed axes.
    std::vector<size_t> crossed;
    for (size_t i = 0; i < n; ++i)
        if (stage.axes[i].crossed) crossed.push_back(i);
    std::vector<size_t> choice = defaults;
    for (size_t i : crossed) choice[i] = 0;
    while (true) {
        add(choice);
        size_t k = crossed.size();
        // Odometer with the last crossed axis fastest, so one blur's downsample factors sit together.
        while (k > 0) {
            size_t axis = crossed[k - 1];
            if (++choice[axis] < stage.axes[axis].values.size()) break;
            choice[axis] = 0;
            --k;
        }
        if (k == 0) break;
    }

    for (size_t i = 0; i < n; ++i) {
        const VariantAxis& a = stage.axes[i];
        if (a.crossed) continue;
        for (size_t value = 0; value < a.values.size(); ++value) {
            std::vector<size_t> single = defaults;
            single[i] = value;
            if (!a.with.empty() && value != a.defaultIndex) {
                const VariantAxis& effects = stage.axes[effectsIndex];
                for (size_t e = 0; e < effects.values.size(); ++e)
                    if (effects.values[e].words[0] == a.with) single[effectsIndex] = e;
            }
            add(single);
        }
    }
    return out;
}

}  // namespace rmfx::accuracy
