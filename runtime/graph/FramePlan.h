#pragma once
// What a frame computes, decided before any GL object exists: the effects asked for, the pass
// graph of every combination of their switches (switching an effect then costs a lookup), and the
// render targets those graphs use with the memory they share. Pure: no GL. The executor runs a
// plan; `rmfx render --explain` prints one; tests check one without a GL context.

#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/Result.h"
#include "core/Value.h"
#include "graph/ContentSkipPlan.h"
#include "graph/PassGraph.h"
#include "graph/ResourceLimits.h"
#include "graph/TargetPlan.h"
#include "model/EffectSelection.h"
#include "model/TargetHealth.h"
#include "model/Workspace.h"

namespace rmfx {

// Who leaves the passes content skip skips out (gl/GlContentSkip.h): a setting of the GL run
// (gl/GlExecutor.h's GlRunSettings), not of the plan. CpuWhenKnown: the GPU through
// conditional rendering, but a pass that comes after the source's answer has arrived (asked for
// without waiting) is left out, or drawn without a condition, by the CPU itself. GpuOnly: always
// the GPU. CpuWaits: the CPU waits for the answer right after the source is measured (a stall: for
// tests that must take the CPU's side).
enum class ContentSkipDecision { CpuWhenKnown, GpuOnly, CpuWaits };

struct FramePlanOptions {
    // The targets the caller reads after a frame. Only the passes they need run, and targets whose
    // lifetimes do not overlap share memory. Empty: every target a running pass writes is an
    // output, so every one can be inspected and none is shared.
    std::vector<std::string> outputs;
    // The effects asked for (--effects); nullopt: the workspace's <output effects>, else all.
    std::optional<std::vector<std::string>> effects;
    // The <input>s an image is given for (rmfx render --input): the passes they replace are culled.
    std::set<std::string> givenInputs;
    bool poolTargets = true;
    // <effect source>: skip on the GPU the effects whose source holds nothing (rmfx render
    // --content-skip off runs them all the same).
    bool contentSkip = true;
    // rmfx render --check: after each pass, inspect on the GPU the target it wrote for NaN, ±Inf,
    // negatives and values at its format's largest (gl/GlHealthCheck.h, model/TargetHealth.h).
    bool checkHealth = false;
    // The most render-target memory a frame may hold (--memory-budget); a workspace that needs
    // more fails before anything is allocated.
    std::size_t memoryBudget = kDefaultMemoryBudget;
};

// One combination of effect switches and the passes it runs.
struct FrameVariant {
    std::set<std::string> switchedOff;
    const PassGraph* graph = nullptr;
    const ContentSkipPlan* contentSkip = nullptr;  // null when content skip has nothing to do or is off
};

struct FramePlan {
    FramePlanOptions options;
    std::set<std::string> askedEffects;
    ShaderPrelude prelude;  // what every shader is compiled with for the effects asked for
    FrameRequest request;   // the outputs resolved; switchedOff empty
    // The graph of every combination of switched-off effects, all on first. With more than 10
    // switched effects, only all on, each one off and all off are prepared.
    std::map<std::set<std::string>, PassGraph> graphs;
    TargetPlan targets;  // memory for the passes of every graph
    // What content skip does with each graph's schedule, by the same key; empty when it is off or
    // no effect has a source.
    std::map<std::set<std::string>, ContentSkipPlan> contentSkip;

    // Targets share memory only when outputs were named.
    bool pooled() const { return options.poolTargets && !options.outputs.empty(); }
    std::vector<const PassGraph*> allGraphs() const;
    // Every pass some combination of switches runs (indices into Workspace::passes, in order).
    std::set<int> runnablePasses() const;
    // The textures a pass that can run samples.
    std::set<std::string> sampledTextures(const Workspace& ws) const;
    // The combination those switched-off effects make; all on when it was not prepared.
    FrameVariant variant(const std::set<std::string>& switchedOff) const;
    // The combination the switch variables' values select.
    FrameVariant variantFor(const Workspace& ws, const std::map<std::string, Value>& values) const;
};

// Each variable's declared value: what a frame starts with.
std::map<std::string, Value> declaredValues(const Workspace& ws);

// The effects asked for and the graph of every combination of their switches (targets left
// empty). Errors name the pass and the combination that has them.
Result<FramePlan> planFramePasses(const Workspace& ws, const FramePlanOptions& options);

// The targets the graphs of `plan` use at `viewport`, formats and scales picked by `values`,
// checked against the limits: no side beyond `maxTargetSize` (the GL's), the memory budget.
Result<TargetPlan> planFrameTargets(const Workspace& ws, const FramePlan& plan, glm::ivec2 viewport,
                                    const std::map<std::string, Value>& values, int maxTargetSize);

// Both, after checking the viewport against `maxTargetSize`: the whole plan for the given values.
Result<FramePlan> planFrame(const Workspace& ws, const FramePlanOptions& options, glm::ivec2 viewport,
                            const std::map<std::string, Value>& values, int maxTargetSize);

// GL textures the plan's targets hold: one per resource, two for one read with frame="previous".
int targetTextureCount(const TargetPlan& plan);

}  // namespace rmfx
