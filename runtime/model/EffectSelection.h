#pragma once
// Which effects (<effect>) a frame computes. The effects asked for are fixed when the executor
// is built (--effects, or the workspace's <output effects>); an asked-for effect with switch
// variables is switched off at run time while all of them are false or zero. Shaders see each
// effect as RMFX_EFFECT_<name>: the constant false when it is left out (its reads compile away),
// a uniform bool when switches decide (no recompile when they change), else true.

#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "core/Result.h"
#include "core/Value.h"
#include "model/Workspace.h"

namespace rmfx {

// `requested` (from --effects) when given, else the workspace's <output effects>, else every
// declared effect. An unknown name is an error listing the declared ones.
Result<std::set<std::string>> selectEffects(const Workspace& ws, const std::optional<std::vector<std::string>>& requested);

// A switch value turns its effect on when any component is non-zero (true for a bool).
bool switchIsOn(const Value& value);

// The effects of `asked` whose switch variables are all off in `values`.
std::set<std::string> switchedOffEffects(const Workspace& ws, const std::set<std::string>& asked,
                                         const std::map<std::string, Value>& values);

// "rmfx_effect_<name>": the uniform bool of an effect with switches.
std::string effectSwitchUniform(const std::string& effect);
std::string effectMacro(const std::string& effect);  // "RMFX_EFFECT_<name>"

// What every shader of the workspace is compiled with for the effects asked for.
struct ShaderPrelude {
    std::vector<std::string> defines;       // "RMFX_EFFECT_glare true", …
    std::vector<std::string> declarations;  // "uniform bool rmfx_effect_glare;", …
};
ShaderPrelude effectPrelude(const Workspace& ws, const std::set<std::string>& asked);

// "glare, streak ghost" → {glare, streak, ghost}: names separated by commas or white space, as
// --effects, <output effects> and a replay case's effects give them.
std::vector<std::string> splitNameList(std::string_view text);

// "glare, streak" (or "none").
std::string joinNames(const std::set<std::string>& names);

}  // namespace rmfx
