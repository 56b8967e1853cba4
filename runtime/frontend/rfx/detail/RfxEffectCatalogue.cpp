#include "frontend/rfx/detail/RfxEffectCatalogue.h"

#include <algorithm>
#include <string_view>

#include "frontend/rfx/detail/RfxElement.h"

namespace rmfx::rfx {

using tinyxml2::XMLElement;

const char* rfxApiName(RfxApi api) {
    switch (api) {
        case RfxApi::OpenGL: return "OpenGL";
        case RfxApi::OpenGLES: return "OpenGL ES";
        case RfxApi::Direct3D: return "Direct3D 9";
    }
    return "?";
}

static std::optional<RfxApi> effectApi(std::string_view tag) {
    if (tag == "RmOpenGLEffect") return RfxApi::OpenGL;
    if (tag == "RmOpenGLESEffect") return RfxApi::OpenGLES;
    if (tag == "RmDirectXEffect") return RfxApi::Direct3D;
    return std::nullopt;
}

RfxCatalogue readCatalogue(const XMLElement* root, const std::string& file, Diagnostics& diagnostics) {
    RfxCatalogue out;
    const XMLElement* ws = root->FirstChildElement("RmEffectWorkspace");
    if (!ws) {
        diagnostics.push_back({Diagnostic::Severity::Error, {file, root->GetLineNum()}, "<RENDER_MONKEY>",
                               "it holds no <RmEffectWorkspace> (a clipboard or registry file has no effects)"});
        return out;
    }
    RfxElement wsElement(ws, file, diagnostics);
    std::string wsName = wsElement.name();
    out.activePath = wsElement.text("ACTIVE_EFFECT", false).value_or("");
    auto add = [&](const XMLElement* e, const XMLElement* group) {
        auto api = effectApi(e->Name());
        if (!api) return;
        RfxEffectEntry entry;
        entry.name = RfxElement(e, file, diagnostics).name();
        entry.path = wsName + "." + (group ? RfxElement(group, file, diagnostics).name() + "." : "") + entry.name;
        entry.api = *api;
        entry.active = entry.path == out.activePath;
        entry.element = e;
        entry.group = group;
        entry.workspace = ws;
        out.effects.push_back(entry);
    };
    for (const XMLElement* e = ws->FirstChildElement(); e; e = e->NextSiblingElement()) {
        if (std::string_view(e->Name()) == "RmEffectGroup") {
            for (const XMLElement* g = e->FirstChildElement(); g; g = g->NextSiblingElement()) add(g, e);
        } else {
            add(e, nullptr);
        }
    }
    if (!out.activePath.empty() && !out.effects.empty()) {
        bool found = false;
        for (const RfxEffectEntry& e : out.effects) found = found || e.active;
        // RenderMonkey 1.0 saved the effect's name alone: the active one, where it names one.
        if (!found && std::count_if(out.effects.begin(), out.effects.end(),
                                    [&](const RfxEffectEntry& e) { return e.name == out.activePath; }) == 1)
            for (RfxEffectEntry& e : out.effects) found = found || (e.active = e.name == out.activePath);
        if (!found)
            wsElement.warning("ACTIVE_EFFECT '" + out.activePath + "' names no effect of the workspace");
    }
    return out;
}

static std::string effectList(const RfxCatalogue& catalogue) {
    std::string list;
    for (const RfxEffectEntry& e : catalogue.effects)
        list += (list.empty() ? "" : ", ") + ("'" + e.path + "'") + " (" + rfxApiName(e.api) + (e.active ? ", active" : "") + ")";
    return list.empty() ? "it has none" : "it has: " + list;
}

const RfxEffectEntry* chooseEffect(const RfxCatalogue& catalogue, const std::string& wanted, const std::string& file,
                                   Diagnostics& diagnostics) {
    auto fail = [&](const std::string& message) -> const RfxEffectEntry* {
        diagnostics.push_back({Diagnostic::Severity::Error, {file, 0}, wanted.empty() ? "" : "--effect " + wanted,
                               message + "; " + effectList(catalogue)});
        return nullptr;
    };
    if (catalogue.effects.empty()) return fail("the workspace holds no effect");
    if (wanted.empty()) {
        for (const RfxEffectEntry& e : catalogue.effects)
            if (e.active) return &e;
        if (catalogue.effects.size() == 1) return &catalogue.effects[0];
        return fail("ACTIVE_EFFECT names no effect; choose one with --effect NAME");
    }
    for (const RfxEffectEntry& e : catalogue.effects)
        if (e.path == wanted) return &e;
    for (const RfxEffectEntry& e : catalogue.effects) {
        size_t dot = e.path.find('.');
        if (dot != std::string::npos && e.path.compare(dot + 1, std::string::npos, wanted) == 0) return &e;
    }
    const RfxEffectEntry* byName = nullptr;
    int count = 0;
    for (const RfxEffectEntry& e : catalogue.effects)
        if (e.name == wanted) byName = &e, ++count;
    if (count == 1) return byName;
    if (count > 1) return fail("several effects are named '" + wanted + "': give the dotted path");
    return fail("no effect '" + wanted + "'");
}

}  // namespace rmfx::rfx
