#include "validation/UnreadArguments.h"

#include <set>
#include <string>

namespace rmfx {
namespace {

// "pass 'a': culled: disabled, enabled="false"; pass 'b': …": the passes that sample `texture` and why each
// does not run in any graph of the plan; "" when none samples it.
std::string samplingPasses(const Workspace& ws, const FramePlan& plan, const std::string& texture) {
    const std::vector<const PassGraph*> graphs = plan.allGraphs();
    const PassGraph* graph = graphs.empty() ? nullptr : graphs.front();
    std::string out;
    for (size_t i = 0; i < ws.passes.size(); ++i) {
        bool samples = false;
        for (const Sampler& s : ws.passes[i].samplers) samples = samples || s.texture == texture;
        if (!samples) continue;
        out += (out.empty() ? "" : "; ") + std::string("pass '") + ws.passes[i].name + "'";
        if (graph && i < graph->nodes.size()) {
            const PassNode& node = graph->nodes[i];
            out += ": " + std::string(passFateName(node.fate)) + (node.why.empty() ? "" : ", " + node.why);
        }
    }
    return out;
}

Diagnostic warningAbout(const Workspace& ws, std::string argument, std::string message) {
    return {Diagnostic::Severity::Warning, {ws.path.string(), 0}, std::move(argument), std::move(message)};
}

}  // namespace

Diagnostics unreadArgumentWarnings(const Workspace& ws, const FramePlanOptions& options,
                                   const std::vector<TextureArgument>& textures, const std::vector<InputArgument>& inputs) {
    Diagnostics out;
    if (textures.empty() && inputs.empty()) return out;
    // A plan that fails is reported by the run itself; nothing to say here.
    Result<FramePlan> plan = planFramePasses(ws, options);
    if (!plan) return out;
    const std::set<std::string> sampled = plan->sampledTextures(ws);

    for (const TextureArgument& t : textures) {
        const std::string argument = "--texture " + t.text;
        if (!sampled.count(t.name)) {
            const std::string passes = samplingPasses(ws, *plan, t.name);
            out.push_back(warningAbout(ws, argument, "no pass that runs samples texture '" + t.name + "', so the file changes nothing" +
                                                         (passes.empty() ? "; no pass samples it" : "; " + passes)));
            continue;
        }
        const Texture* texture = ws.findTexture(t.name);
        if (!texture || texture->readWhenVariable.empty()) continue;
        const Variable* v = ws.findVariable(texture->readWhenVariable);
        if (!v) continue;
        Result<Value> wanted = parseValue(v->value.type, texture->readWhenValue);
        if (!wanted || *wanted == v->value) continue;
        out.push_back(warningAbout(ws, argument, "the passes read texture '" + t.name + "' only while " + v->name + " is " +
                                                     texture->readWhenValue + " (it is " + formatValue(v->value) +
                                                     "), so the file changes nothing: add --set " + v->name + "=" +
                                                     texture->readWhenValue));
    }
    for (const InputArgument& input : inputs) {
        const std::string name = !input.name.empty() ? input.name : ws.inputs.size() == 1 ? ws.inputs.front().name : "";
        if (name.empty() || sampled.count(name)) continue;
        const std::string passes = samplingPasses(ws, *plan, name);
        out.push_back(warningAbout(ws, "--input " + input.text, "no pass that runs samples input '" + name + "', so the image changes nothing" +
                                                                    (passes.empty() ? "; no pass samples it" : "; " + passes)));
    }
    return out;
}

}  // namespace rmfx
