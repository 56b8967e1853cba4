#include "graph/ResourceLimits.h"

#include <algorithm>
#include <string>
#include <vector>

#include "graph/FrameExplanation.h"

namespace rmfx {

namespace {

std::string sizeText(glm::ivec2 size) { return std::to_string(size.x) + "x" + std::to_string(size.y); }

}  // namespace

Result<void> checkViewportLimits(glm::ivec2 viewport, const ResourceLimits& limits, const SourceLocation& where) {
    if (viewport.x <= limits.maxTargetSize && viewport.y <= limits.maxTargetSize) return {};
    return Diagnostics{{Diagnostic::Severity::Error, where, "",
             "viewport size " + sizeText(viewport) + " is larger than this GL allows (" +
                 std::to_string(limits.maxTargetSize) + " per side); nothing was allocated"}};
}

Result<void> checkPlanLimits(const TargetPlan& plan, const ResourceLimits& limits, const SourceLocation& workspace) {
    Diagnostics d;
    for (const PlannedTarget& t : plan.targets) {
        if (t.resource < 0) continue;
        if (t.size.x > limits.maxTargetSize || t.size.y > limits.maxTargetSize)
            d.push_back({Diagnostic::Severity::Error, t.where, "<target name=\"" + t.name + "\">",
                         "target '" + t.name + "' would be " + sizeText(t.size) + ", larger than this GL allows (" +
                             std::to_string(limits.maxTargetSize) + " per side); nothing was allocated"});
    }
    if (!d.empty() || plan.allocatedBytes <= limits.memoryBudget) return d;
    std::vector<const PlannedTarget*> largest;
    for (const PlannedTarget& t : plan.targets)
        if (t.resource >= 0) largest.push_back(&t);
    std::sort(largest.begin(), largest.end(), [](auto* a, auto* b) { return a->bytes > b->bytes; });
    std::string names;
    for (size_t i = 0; i < largest.size() && i < 3; ++i)
        names += (i ? ", " : "") + ("'" + largest[i]->name + "' " + sizeText(largest[i]->size) + " " +
                                    formatBytes(largest[i]->bytes));
    d.push_back({Diagnostic::Severity::Error, workspace, "",
                 "the render targets need " + formatBytes(plan.allocatedBytes) + ", more than the memory budget of " +
                     formatBytes(limits.memoryBudget) + " (largest: " + names +
                     "); nothing was allocated (raise it with --memory-budget MiB)"});
    return d;
}

}  // namespace rmfx
