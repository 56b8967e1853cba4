#include "graph/TargetPlan.h"

#include <algorithm>
#include <set>

#include <glm/common.hpp>

namespace rmfx {

std::size_t targetBytes(TargetFormat format, glm::ivec2 size, bool mipmaps, bool depth, bool history) {
    std::size_t pixels = 0;
    for (glm::ivec2 level = size;; level = glm::max(level / 2, glm::ivec2(1))) {
        pixels += static_cast<std::size_t>(level.x) * static_cast<std::size_t>(level.y);
        if (!mipmaps || (level.x == 1 && level.y == 1)) break;
    }
    std::size_t bytes = pixels * static_cast<std::size_t>(targetFormatBytesPerPixel(format)) * (history ? 2 : 1);
    if (depth) bytes += static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y) * 4;
    return bytes;
}

int TargetPlan::find(const std::string& name) const {
    for (size_t i = 0; i < targets.size(); ++i)
        if (targets[i].name == name) return static_cast<int>(i);
    return -1;
}

Result<TargetPlan> planTargets(const Workspace& ws, const std::vector<const PassGraph*>& graphs, glm::ivec2 viewport,
                               const std::map<std::string, Value>& values, bool pool) {
    TargetPlan plan;
    for (const RenderTarget& t : ws.targets) {
        PlannedTarget p;
        p.name = t.name;
        p.spec = &t;
        const Value* value = nullptr;
        if (auto it = values.find(t.formatVariable); it != values.end()) value = &it->second;
        auto format = selectTargetFormat(t, value);
        if (!format) return Error{formatChoiceError(t, value)};
        p.format = *format;
        const Value* scaleValue = nullptr;
        if (auto it = values.find(t.scaleVariable); it != values.end()) scaleValue = &it->second;
        auto size = selectTargetSize(t, scaleValue);
        if (!size) return Error{scaleChoiceError(t, scaleValue)};
        p.size = resolveTargetSize(*size, viewport);
        p.mipmaps = t.mipmaps;
        p.initial = t.initial;
        p.where = t.where;
        plan.targets.push_back(p);
    }
    if (ws.output.target.empty()) {
        PlannedTarget p;
        p.name = Workspace::implicitOutputName;
        p.format = ws.output.format;
        p.size = viewport;
        p.where = ws.output.where;
        plan.targets.push_back(p);
    }

    // Lifetimes in pass indices. A target read with frame="previous" is double-buffered, and
    // both it and a target a pass loads before any pass writes it keep their contents between frames.
    auto touch = [&](const std::string& name, int position) {
        int i = plan.find(name);
        if (i < 0) return;
        PlannedTarget& t = plan.targets[static_cast<size_t>(i)];
        t.firstUse = t.used ? std::min(t.firstUse, position) : position;
        t.used = true;
        t.lastUse = std::max(t.lastUse, position);
    };
    const int end = static_cast<int>(ws.passes.size());
    std::set<std::string> carriedTargets, outputs;
    for (const PassGraph* graph : graphs) {
        carriedTargets.insert(graph->carriedTargets.begin(), graph->carriedTargets.end());
        outputs.insert(graph->outputs.begin(), graph->outputs.end());
        for (int index : graph->schedule) {
            const PassNode& node = graph->nodes[static_cast<size_t>(index)];
            const std::vector<std::string>& skipped = node.skippedInputs;
            for (const Sampler& s : node.pass->samplers) {
                if (s.target.empty() || std::find(skipped.begin(), skipped.end(), s.target) != skipped.end()) continue;
                if (s.previousFrame)
                    if (int i = plan.find(s.target); i >= 0) plan.targets[static_cast<size_t>(i)].history = true;
                touch(s.target, index);
            }
            touch(node.target, index);
            if (!node.gate.empty()) touch(node.gate, index);  // counted before the effect's first pass
            const Pass& p = *node.pass;
            if (p.depth.test || p.depth.write || p.clear.depth)
                if (int i = plan.find(node.target); i >= 0) plan.targets[static_cast<size_t>(i)].depth = true;
        }
    }
    for (PlannedTarget& t : plan.targets) {
        t.carried = t.history || carriedTargets.count(t.name) > 0;
        t.bytes = targetBytes(t.format, t.size, t.mipmaps, t.depth, t.history);
        // Every declared target on its own, with the depth and history any enabled pass gives it.
        bool depth = false, history = false;
        for (const Pass& p : ws.passes) {
            if (!p.enabled) continue;
            depth = depth || (ws.passTargetName(p) == t.name && (p.depth.test || p.depth.write || p.clear.depth));
            for (const Sampler& s : p.samplers) history = history || (s.target == t.name && s.previousFrame);
        }
        plan.declaredBytes += targetBytes(t.format, t.size, t.mipmaps, depth, history);
    }
    for (const std::string& output : outputs)
        if (int i = plan.find(output); i >= 0 && plan.targets[static_cast<size_t>(i)].used)
            plan.targets[static_cast<size_t>(i)].lastUse = end;

    std::vector<int> order;
    for (size_t i = 0; i < plan.targets.size(); ++i)
        if (plan.targets[i].used) order.push_back(static_cast<int>(i));
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return plan.targets[static_cast<size_t>(a)].firstUse < plan.targets[static_cast<size_t>(b)].firstUse;
    });
    std::vector<int> resourceEnd;  // last use of the newest target in each resource
    for (int index : order) {
        PlannedTarget& t = plan.targets[static_cast<size_t>(index)];
        int chosen = -1;
        if (pool && !t.carried) {
            for (size_t r = 0; r < plan.resources.size(); ++r) {
                const TargetResource& res = plan.resources[r];
                const PlannedTarget& first = plan.targets[static_cast<size_t>(res.targets.front())];
                if (!first.carried && res.format == t.format && res.size == t.size && res.mipmaps == t.mipmaps &&
                    res.depth == t.depth && resourceEnd[r] < t.firstUse) {
                    chosen = static_cast<int>(r);
                    break;
                }
            }
        }
        if (chosen < 0) {
            TargetResource res;
            res.format = t.format;
            res.size = t.size;
            res.mipmaps = t.mipmaps;
            res.depth = t.depth;
            res.history = t.history;
            res.initial = t.initial;
            res.bytes = t.bytes;
            plan.resources.push_back(res);
            resourceEnd.push_back(-1);
            chosen = static_cast<int>(plan.resources.size() - 1);
        }
        t.resource = chosen;
        plan.resources[static_cast<size_t>(chosen)].targets.push_back(index);
        resourceEnd[static_cast<size_t>(chosen)] = t.lastUse;
    }
    for (const TargetResource& r : plan.resources) plan.allocatedBytes += r.bytes;
    return plan;
}

}  // namespace rmfx
