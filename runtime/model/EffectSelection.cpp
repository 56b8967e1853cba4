#include "model/EffectSelection.h"

namespace rmfx {

std::vector<std::string> splitNameList(std::string_view text) {
    std::vector<std::string> names;
    std::string name;
    for (char c : text) {
        if (c == ',' || c == ' ' || c == '\t' || c == '\n' || c == '\r') {
            if (!name.empty()) names.push_back(name);
            name.clear();
        } else {
            name += c;
        }
    }
    if (!name.empty()) names.push_back(name);
    return names;
}

std::string joinNames(const std::set<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? "none" : out;
}

Result<std::set<std::string>> selectEffects(const Workspace& ws, const std::optional<std::vector<std::string>>& requested) {
    std::set<std::string> declared;
    for (const Effect& e : ws.effects) declared.insert(e.name);
    const std::optional<std::vector<std::string>>& names = requested ? requested : ws.output.effects;
    if (!names) return declared;
    std::set<std::string> asked;
    for (const std::string& name : *names) {
        if (!declared.count(name))
            return Error{"no effect named '" + name + "' in " + ws.path.string() +
                         (declared.empty() ? " (it declares no <effect>)" : " (it has: " + joinNames(declared) + ")")};
        asked.insert(name);
    }
    return asked;
}

bool switchIsOn(const Value& value) {
    for (int i = 0; i < componentCount(value.type); ++i)
        if (value.data[static_cast<size_t>(i)] != 0.0f) return true;
    return false;
}

std::set<std::string> switchedOffEffects(const Workspace& ws, const std::set<std::string>& asked,
                                         const std::map<std::string, Value>& values) {
    std::set<std::string> off;
    for (const Effect& e : ws.effects) {
        if (!asked.count(e.name) || e.switches.empty()) continue;
        bool on = false;
        for (const std::string& s : e.switches) {
            auto it = values.find(s);
            on = on || (it != values.end() && switchIsOn(it->second));
        }
        if (!on) off.insert(e.name);
    }
    return off;
}

std::string effectSwitchUniform(const std::string& effect) { return "rmfx_effect_" + effect; }
std::string effectMacro(const std::string& effect) { return "RMFX_EFFECT_" + effect; }

ShaderPrelude effectPrelude(const Workspace& ws, const std::set<std::string>& asked) {
    ShaderPrelude prelude;
    for (const Effect& e : ws.effects) {
        if (!asked.count(e.name)) {
            prelude.defines.push_back(effectMacro(e.name) + " false");
        } else if (e.switches.empty()) {
            prelude.defines.push_back(effectMacro(e.name) + " true");
        } else {
            prelude.defines.push_back(effectMacro(e.name) + " " + effectSwitchUniform(e.name));
            prelude.declarations.push_back("uniform bool " + effectSwitchUniform(e.name) + ";");
        }
    }
    return prelude;
}

}  // namespace rmfx
