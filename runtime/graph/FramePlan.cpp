#include "graph/FramePlan.h"

namespace rmfx {
namespace {

Diagnostics workspaceError(const Workspace& ws, const std::string& element, const std::string& message,
                           const SourceLocation* where = nullptr) {
    return {{Diagnostic::Severity::Error, where ? *where : SourceLocation{ws.path.string(), 0}, element, message}};
}

// No outputs named: every target a running pass writes, so every one can be inspected.
std::vector<std::string> everyWrittenTarget(const Workspace& ws, const std::set<std::string>& askedEffects,
                                            const std::set<std::string>& givenInputs) {
    std::set<std::string> written;
    for (size_t i = 0; i < ws.passes.size(); ++i) {
        const Pass& p = ws.passes[i];
        const Effect* e = ws.effectOfPass(p.name);
        if (p.enabled && (!e || askedEffects.count(e->name)) && !cullingByInputs(ws, givenInputs, static_cast<int>(i)))
            written.insert(ws.passTargetName(p));
    }
    std::vector<std::string> outputs;
    for (const RenderTarget& t : ws.targets)
        if (written.count(t.name)) outputs.push_back(t.name);
    if (written.count(Workspace::implicitOutputName) && ws.output.target.empty())
        outputs.push_back(Workspace::implicitOutputName);
    return outputs;
}

std::vector<std::set<std::string>> switchCombinations(const std::vector<std::string>& switched) {
    std::vector<std::set<std::string>> combinations;
    if (switched.size() <= 10) {
        for (unsigned mask = 0; mask < (1u << switched.size()); ++mask) {
            std::set<std::string> off;
            for (size_t k = 0; k < switched.size(); ++k)
                if (mask & (1u << k)) off.insert(switched[k]);
            combinations.push_back(off);
        }
    } else {
        combinations.push_back({});
        for (const std::string& e : switched) combinations.push_back({e});
        combinations.push_back(std::set<std::string>(switched.begin(), switched.end()));
    }
    return combinations;
}

}  // namespace

std::vector<const PassGraph*> FramePlan::allGraphs() const {
    std::vector<const PassGraph*> all;
    for (auto& [off, g] : graphs) all.push_back(&g);
    return all;
}

std::set<int> FramePlan::runnablePasses() const {
    std::set<int> runnable;
    for (auto& [off, g] : graphs) runnable.insert(g.schedule.begin(), g.schedule.end());
    return runnable;
}

std::set<std::string> FramePlan::sampledTextures(const Workspace& ws) const {
    std::set<std::string> sampled;
    for (int index : runnablePasses())
        for (const Sampler& s : ws.passes[static_cast<size_t>(index)].samplers)
            if (!s.texture.empty()) sampled.insert(s.texture);
    return sampled;
}

FrameVariant FramePlan::variant(const std::set<std::string>& switchedOff) const {
    auto it = graphs.find(switchedOff);
    if (it == graphs.end()) it = graphs.find({});  // more switches than prepared: run them all
    if (it == graphs.end()) return {};
    auto skip = contentSkip.find(it->first);
    return {it->first, &it->second, skip == contentSkip.end() ? nullptr : &skip->second};
}

FrameVariant FramePlan::variantFor(const Workspace& ws, const std::map<std::string, Value>& values) const {
    return variant(switchedOffEffects(ws, askedEffects, values));
}

std::map<std::string, Value> declaredValues(const Workspace& ws) {
    std::map<std::string, Value> values;
    for (const Variable& v : ws.variables) values[v.name] = v.value;
    return values;
}

Result<FramePlan> planFramePasses(const Workspace& ws, const FramePlanOptions& options) {
    auto asked = selectEffects(ws, options.effects);
    if (!asked) return Result<FramePlan>::failure(workspaceError(ws, "", asked.error()));
    FramePlan plan;
    plan.options = options;
    plan.askedEffects = *asked;
    plan.prelude = effectPrelude(ws, plan.askedEffects);
    plan.request.effects = plan.askedEffects;
    plan.request.givenInputs = options.givenInputs;
    plan.request.contentSkip = options.contentSkip;
    plan.request.outputs =
        options.outputs.empty() ? everyWrittenTarget(ws, plan.askedEffects, options.givenInputs) : options.outputs;
    std::vector<std::string> switched;
    for (const Effect& e : ws.effects)
        if (plan.askedEffects.count(e.name) && !e.switches.empty()) switched.push_back(e.name);
    Diagnostics errors;
    for (const std::set<std::string>& off : switchCombinations(switched)) {
        FrameRequest request = plan.request;
        request.switchedOff = off;
        Result<PassGraph> g = buildPassGraph(ws, request);
        if (!g) {
            Diagnostics found = g.takeDiagnostics();
            std::string when = off.empty() ? "" : " (with effects " + joinNames(off) + " switched off)";
            for (Diagnostic& diagnostic : found) diagnostic.message += when;
            errors.insert(errors.end(), found.begin(), found.end());
            continue;
        }
        plan.graphs.emplace(off, std::move(*g));
    }
    if (hasErrors(errors)) return Result<FramePlan>::failure(std::move(errors));
    if (options.contentSkip && hasSourcedEffects(ws))
        for (auto& [off, g] : plan.graphs) plan.contentSkip.emplace(off, planContentSkip(ws, g.schedule, options.outputs));
    return plan;
}

Result<TargetPlan> planFrameTargets(const Workspace& ws, const FramePlan& plan, glm::ivec2 viewport,
                                    const std::map<std::string, Value>& values, int maxTargetSize) {
    auto valueOf = [&](const std::string& name) -> const Value* {
        auto it = values.find(name);
        return it == values.end() ? nullptr : &it->second;
    };
    for (const RenderTarget& t : ws.targets) {
        std::string element = "<target name=\"" + t.name + "\">";
        if (!selectTargetFormat(t, valueOf(t.formatVariable)))
            return Result<TargetPlan>::failure(workspaceError(ws, element, formatChoiceError(t, valueOf(t.formatVariable)), &t.where));
        if (!selectTargetSize(t, valueOf(t.scaleVariable)))
            return Result<TargetPlan>::failure(workspaceError(ws, element, scaleChoiceError(t, valueOf(t.scaleVariable)), &t.where));
    }
    auto planned = planTargets(ws, plan.allGraphs(), viewport, values, plan.pooled());
    if (!planned) return Result<TargetPlan>::failure(workspaceError(ws, "", planned.error()));
    const ResourceLimits limits{maxTargetSize, plan.options.memoryBudget};
    if (Result<void> fits = checkPlanLimits(*planned, limits, {ws.path.string(), 0}); !fits)
        return Result<TargetPlan>::failure(std::move(fits).diagnostics());
    return std::move(*planned);
}

Result<FramePlan> planFrame(const Workspace& ws, const FramePlanOptions& options, glm::ivec2 viewport,
                            const std::map<std::string, Value>& values, int maxTargetSize) {
    const ResourceLimits limits{maxTargetSize, options.memoryBudget};
    if (Result<void> fits = checkViewportLimits(viewport, limits, {ws.path.string(), 0}); !fits)
        return Result<FramePlan>::failure(std::move(fits).diagnostics());
    auto plan = planFramePasses(ws, options);
    if (!plan) return plan;
    auto targets = planFrameTargets(ws, *plan, viewport, values, maxTargetSize);
    if (!targets) return Result<FramePlan>::failure(targets.takeDiagnostics());
    plan->targets = std::move(*targets);
    return plan;
}

int targetTextureCount(const TargetPlan& plan) {
    int count = 0;
    for (const TargetResource& r : plan.resources) count += r.history ? 2 : 1;
    return count;
}

}  // namespace rmfx
