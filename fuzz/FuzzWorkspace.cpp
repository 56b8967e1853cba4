// Fuzz target "workspace": the bytes as workspace XML (with the files it names, FuzzInputFiles.h),
// parsed, then taken through checkParsedWorkspace (FuzzWorkspace.h). Property: every variable's
// value, formatted and applied as an override, reads back as the same value (formatValue is
// parseValue's inverse).

#include <map>

#include "frontend/workspace/WorkspaceDependencies.h"
#include "frontend/workspace/WorkspaceParser.h"
#include "fuzz/FuzzEntries.h"
#include "fuzz/FuzzInputFiles.h"
#include "fuzz/FuzzWorkspace.h"
#include "graph/PassGraph.h"
#include "graph/ResourceLimits.h"
#include "graph/TargetPlan.h"
#include "model/EffectSelection.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::fuzz {
namespace {

void checkOverridesRoundTrip(Workspace ws) {
    std::vector<std::pair<std::string, std::string>> overrides;
    for (const Variable& v : ws.variables) overrides.emplace_back(v.name, formatValue(v.value));
    Workspace before = ws;
    Diagnostics found = applyOverrides(ws, overrides).diagnostics();
    fuzzCheck(!hasErrors(found), "a variable's own value, formatted, is refused as --set: " + formatAll(found));
    for (size_t i = 0; i < ws.variables.size(); ++i)
        fuzzCheck(ws.variables[i].value == before.variables[i].value,
                  "variable '" + ws.variables[i].name + "' does not read back as " + formatValue(before.variables[i].value));
    fuzzCheck(!applyOverrides(ws, {{"rmfx fuzz: no such variable", "1"}}).ok(), "--set of an undeclared variable is accepted");
}

// GlExecutor's steps before its first GL call.
void planFrame(const Workspace& ws) {
    auto asked = selectEffects(ws, std::nullopt);
    if (!asked) return;
    FrameRequest request;
    request.effects = *asked;
    std::map<std::string, Value> values;
    for (const Variable& v : ws.variables) values.emplace(v.name, v.value);
    request.switchedOff = switchedOffEffects(ws, *asked, values);
    Result<PassGraph> built = buildPassGraph(ws, request);
    formatAll(built.diagnostics());
    if (!built) return;
    PassGraph& graph = *built;
    for (const RenderTarget& t : ws.targets) {
        auto valueOf = [&](const std::string& name) -> const Value* {
            auto it = values.find(name);
            return it == values.end() ? nullptr : &it->second;
        };
        if (!selectTargetFormat(t, valueOf(t.formatVariable)) || !selectTargetSize(t, valueOf(t.scaleVariable))) return;
    }
    glm::ivec2 viewport{ws.width, ws.height};
    ResourceLimits limits;
    if (!checkViewportLimits(viewport, limits, {ws.path.string(), 0})) return;
    for (bool pool : {false, true}) {
        auto plan = planTargets(ws, {&graph}, viewport, values, pool);
        if (plan) formatAll(checkPlanLimits(*plan, limits, {ws.path.string(), 0}).diagnostics());
    }
}

}  // namespace

void checkParsedWorkspace(const Result<Workspace>& parsed) {
    formatAll(parsed.diagnostics());
    fuzzCheck(parsed.ok() == !hasErrors(parsed.diagnostics()),
              "the front end returned a workspace together with errors, or neither");
    if (!parsed) return;
    const Workspace& ws = *parsed;
    Diagnostics found = validateWorkspace(ws, {.compileShaders = false}).diagnostics();
    formatAll(found);
    findWorkspaceDependencies(ws);
    if (hasErrors(found)) return;  // what loadWorkspace refuses goes no further
    checkOverridesRoundTrip(ws);
    planFrame(ws);
}

void fuzzWorkspace(const std::uint8_t* data, std::size_t size) {
    FuzzInput input = splitFuzzInput({reinterpret_cast<const char*>(data), size});
    // Two folders deep, so that seeds naming "../../media/x.png" find their files.
    std::filesystem::path folder = freshScratchFolder() / "a" / "b" / "ws";
    std::filesystem::create_directories(folder);
    writeParts(input.parts, folder);
    checkParsedWorkspace(parseWorkspaceText(input.main, folder / "fuzz.xml", folder));
}

}  // namespace rmfx::fuzz
