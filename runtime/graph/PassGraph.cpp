#include "graph/PassGraph.h"

#include <algorithm>
#include <deque>
#include <map>

#include "model/EffectSelection.h"

namespace rmfx {
namespace {

// A full-screen triangle without blending replaces every pixel; anything else keeps some of what
// the target held unless the pass clears it first.
bool passLoadsTarget(const Pass& p) {
    if (p.blend.enabled) return true;
    bool fullscreen = p.draw.file.empty() && p.draw.mesh == BuiltinMesh::FullscreenTriangle;
    return !fullscreen && !p.clear.color;
}

std::string samplerLabel(const Sampler& s) { return "<sampler name=\"" + s.uniform + "\">"; }

std::string inQuotes(const std::string& name) { return "'" + name + "'"; }

bool samplesTexture(const Pass& p, const std::string& texture) {
    for (const Sampler& s : p.samplers)
        if (s.texture == texture) return true;
    return false;
}

}  // namespace

std::optional<InputCulling> cullingByInputs(const Workspace& ws, const std::set<std::string>& givenInputs, int index) {
    const Pass& pass = ws.passes[static_cast<size_t>(index)];
    const std::string target = ws.passTargetName(pass);
    for (const ImageInput& input : ws.inputs) {
        if (input.replaces.empty()) continue;
        const bool given = givenInputs.count(input.name) != 0;
        if (!given && samplesTexture(pass, input.name))
            return InputCulling{PassFate::InputNotGiven, "no image given for input '" + input.name + "' (rmfx render --input " +
                                                             input.name + "=FILE): the workspace draws " +
                                                             inQuotes(input.replaces) + " itself"};
        if (!given || target != input.replaces) continue;
        int first = -1;
        for (size_t i = 0; i < ws.passes.size() && first < 0; ++i)
            if (samplesTexture(ws.passes[i], input.name)) first = static_cast<int>(i);
        if (first >= 0 && index < first)
            return InputCulling{PassFate::InputGiven,
                                inQuotes(input.replaces) + " comes from the image given for input '" + input.name + "'"};
    }
    return std::nullopt;
}

namespace {

int lastWriterBefore(const std::vector<PassNode>& nodes, const std::string& target, int before) {
    for (int j = before - 1; j >= 0; --j)
        if (nodes[static_cast<size_t>(j)].active && nodes[static_cast<size_t>(j)].target == target) return j;
    return -1;
}

// The effect every enabled writer of `target` belongs to; null when a writer belongs to none or
// the writers belong to different effects.
const Effect* owningEffect(const std::vector<PassNode>& nodes, const std::string& target) {
    const Effect* owner = nullptr;
    for (const PassNode& n : nodes) {
        if (!n.pass->enabled || n.target != target) continue;
        if (!n.effect || (owner && owner != n.effect)) return nullptr;
        owner = n.effect;
    }
    return owner;
}

}  // namespace

const char* passFateName(PassFate fate) {
    switch (fate) {
        case PassFate::Run: return "run";
        case PassFate::Disabled: return "culled: disabled";
        case PassFate::EffectLeftOut: return "culled: effect left out";
        case PassFate::EffectSwitchedOff: return "culled: effect switched off";
        case PassFate::InputGiven: return "culled: input given";
        case PassFate::InputNotGiven: return "culled: input not given";
        case PassFate::NotNeeded: return "culled: not needed";
    }
    return "?";
}

int PassGraph::passIndex(const std::string& name) const {
    for (size_t i = 0; i < nodes.size(); ++i)
        if (nodes[i].pass->name == name) return static_cast<int>(i);
    return -1;
}

Result<PassGraph> buildPassGraph(const Workspace& ws, const FrameRequest& request) {
    Diagnostics diagnostics;
    PassGraph g;
    const int n = static_cast<int>(ws.passes.size());
    g.nodes.resize(ws.passes.size());
    for (size_t i = 0; i < ws.passes.size(); ++i) {
        PassNode& node = g.nodes[i];
        const Pass& pass = ws.passes[i];
        node.pass = &pass;
        node.target = ws.passTargetName(pass);
        node.effect = ws.effectOfPass(pass.name);
        node.loadsTarget = passLoadsTarget(pass);
        std::optional<InputCulling> culled =
            pass.enabled ? cullingByInputs(ws, request.givenInputs, static_cast<int>(i)) : std::nullopt;
        if (!pass.enabled) {
            node.fate = PassFate::Disabled;
            node.why = "enabled=\"false\"";
        } else if (culled) {
            node.fate = culled->fate;
            node.why = std::move(culled->why);
        } else if (node.effect && !request.effects.count(node.effect->name)) {
            node.fate = PassFate::EffectLeftOut;
            node.why = "effect '" + node.effect->name + "' not asked for (asked for: " + joinNames(request.effects) + ")";
        } else if (node.effect && request.switchedOff.count(node.effect->name)) {
            std::set<std::string> switches(node.effect->switches.begin(), node.effect->switches.end());
            node.fate = PassFate::EffectSwitchedOff;
            node.why = "effect '" + node.effect->name + "' switched off (" + joinNames(switches) + " all off)";
        } else {
            node.active = true;
        }
    }

    // Dependencies of the active passes, each with the reason it is needed. A read with nothing to
    // read is an error only if the pass turns out to be needed.
    struct MissingInput {
        int pass;
        const Sampler* sampler;
    };
    std::vector<MissingInput> missing;
    std::vector<std::vector<std::string>> inputWhy(g.nodes.size()), carriedWhy(g.nodes.size());
    for (int i = 0; i < n; ++i) {
        PassNode& node = g.nodes[static_cast<size_t>(i)];
        if (!node.active) continue;
        const std::string& name = node.pass->name;
        for (const Sampler& s : node.pass->samplers) {
            if (s.target.empty()) continue;
            if (s.previousFrame) {
                g.carriedTargets.insert(s.target);
                int j = lastWriterBefore(g.nodes, s.target, n);
                if (j < 0) continue;  // keeps its initial contents
                node.carried.push_back(j);
                carriedWhy[static_cast<size_t>(i)].push_back(inQuotes(name) + " reads last frame's " + inQuotes(s.target));
                continue;
            }
            int j = lastWriterBefore(g.nodes, s.target, i);
            if (j >= 0) {
                node.inputs.push_back(j);
                inputWhy[static_cast<size_t>(i)].push_back(inQuotes(name) + " reads " + inQuotes(s.target));
                continue;
            }
            const Effect* owner = owningEffect(g.nodes, s.target);
            if (owner && owner != node.effect &&
                (!request.effects.count(owner->name) || request.switchedOff.count(owner->name))) {
                node.skippedInputs.push_back(s.target);
                continue;
            }
            missing.push_back({i, &s});
        }
        if (request.contentSkip && node.effect && !node.effect->gate.empty()) {
            int j = lastWriterBefore(g.nodes, node.effect->gate, i);
            if (j >= 0) {
                node.gate = node.effect->gate;
                node.inputs.push_back(j);
                inputWhy[static_cast<size_t>(i)].push_back("content skip counts " + inQuotes(node.gate) + " to decide whether effect " +
                                                           inQuotes(node.effect->name) + " runs");
            }
        }
        if (node.loadsTarget) {
            int j = lastWriterBefore(g.nodes, node.target, i);
            if (j >= 0) {
                node.inputs.push_back(j);
                inputWhy[static_cast<size_t>(i)].push_back(inQuotes(name) + " draws over " + inQuotes(node.target));
            } else {
                g.carriedTargets.insert(node.target);
            }
        }
    }

    g.outputs = request.outputs.empty() ? std::vector<std::string>{ws.outputTargetName()} : request.outputs;
    std::vector<bool> needed(g.nodes.size(), false);
    std::deque<int> work;
    auto need = [&](int j, const std::string& why) {
        if (needed[static_cast<size_t>(j)]) return;
        needed[static_cast<size_t>(j)] = true;
        g.nodes[static_cast<size_t>(j)].why = why;
        work.push_back(j);
    };
    for (const std::string& output : g.outputs) {
        if (!ws.canReadTarget(output)) {
            diagnostics.push_back({Diagnostic::Severity::Error, {ws.path.string(), 0}, "",
                                   "no target named '" + output + "' to compute (" + ws.describeTargets() + ")"});
            continue;
        }
        int j = lastWriterBefore(g.nodes, output, n);
        if (j >= 0) {
            need(j, "writes " + inQuotes(output) + ", which is asked for");
            continue;
        }
        bool writtenWhenOn = false;
        for (const PassNode& node : g.nodes)
            writtenWhenOn = writtenWhenOn || (node.target == output && node.fate == PassFate::EffectSwitchedOff);
        if (!writtenWhenOn) {
            // A shadow map's first step, alone in its file, draws only into its own target.
            std::vector<std::string> written;
            for (const PassNode& node : g.nodes)
                if (node.active && std::find(written.begin(), written.end(), node.target) == written.end())
                    written.push_back(node.target);
            std::string those;
            for (const std::string& t : written) those += (those.empty() ? "" : ", ") + inQuotes(t);
            diagnostics.push_back({Diagnostic::Severity::Error, {ws.path.string(), 0}, "",
                                   "no running pass writes target '" + output + "', which is asked for" +
                                       (written.empty() ? std::string() : "; the running passes write " + those + " (--target NAME)")});
        }
    }
    while (!work.empty()) {
        int k = work.front();
        work.pop_front();
        const PassNode& node = g.nodes[static_cast<size_t>(k)];
        for (size_t a = 0; a < node.inputs.size(); ++a) need(node.inputs[a], inputWhy[static_cast<size_t>(k)][a]);
        for (size_t a = 0; a < node.carried.size(); ++a) need(node.carried[a], carriedWhy[static_cast<size_t>(k)][a]);
    }

    for (int i = 0; i < n; ++i) {
        if (!needed[static_cast<size_t>(i)]) continue;
        for (const Sampler& s : g.nodes[static_cast<size_t>(i)].pass->samplers)
            if (ws.findInput(s.texture) && !request.givenInputs.count(s.texture) && ws.findTexture(s.texture)->files.empty())
                diagnostics.push_back({Diagnostic::Severity::Error, s.where, samplerLabel(s),
                                       "pass '" + ws.passes[static_cast<size_t>(i)].name + "' samples input '" + s.texture +
                                           "', and no image was given for it (rmfx render --input " + s.texture + "=FILE)"});
    }
    for (const MissingInput& m : missing)
        if (needed[static_cast<size_t>(m.pass)])
            diagnostics.push_back({Diagnostic::Severity::Error, m.sampler->where, samplerLabel(*m.sampler),
                                   "pass '" + ws.passes[static_cast<size_t>(m.pass)].name + "' reads target '" +
                                       m.sampler->target + "', which no running pass wrote earlier in the frame"});
    for (int i = 0; i < n; ++i) {
        PassNode& node = g.nodes[static_cast<size_t>(i)];
        if (!node.active) continue;
        if (needed[static_cast<size_t>(i)]) {
            node.fate = PassFate::Run;
            g.schedule.push_back(i);
            continue;
        }
        node.fate = PassFate::NotNeeded;
        node.why = "nothing asked for reads " + inQuotes(node.target);
        // A later pass that replaces the target before anything reads it makes this one dead.
        for (int k = i + 1; k < n; ++k) {
            const PassNode& later = g.nodes[static_cast<size_t>(k)];
            if (!later.active) continue;
            bool reads = false;
            for (const Sampler& s : later.pass->samplers) reads = reads || (s.target == node.target && !s.previousFrame);
            if (reads) break;
            if (later.target == node.target) {
                if (!later.loadsTarget) node.why = inQuotes(later.pass->name) + " replaces " + inQuotes(node.target) + " before anything reads it";
                break;
            }
        }
    }
    if (hasErrors(diagnostics)) return Result<PassGraph>::failure(std::move(diagnostics));
    return {std::move(g), std::move(diagnostics)};
}

Diagnostics checkPassOrder(const Workspace& ws) {
    Diagnostics out;
    const int n = static_cast<int>(ws.passes.size());
    auto writes = [&](int i) { return ws.passTargetName(ws.passes[static_cast<size_t>(i)]); };
    // x → y when pass x samples this frame's contents of a target pass y writes, in any order.
    struct Edge {
        int to;
        std::string target;
    };
    std::vector<std::vector<Edge>> edges(ws.passes.size());
    for (int x = 0; x < n; ++x) {
        const Pass& p = ws.passes[static_cast<size_t>(x)];
        if (!p.enabled) continue;
        for (const Sampler& s : p.samplers) {
            if (s.target.empty() || s.previousFrame) continue;
            for (int y = 0; y < n; ++y)
                if (y != x && ws.passes[static_cast<size_t>(y)].enabled && writes(y) == s.target)
                    edges[static_cast<size_t>(x)].push_back({y, s.target});
        }
    }
    for (int i = 0; i < n; ++i) {
        const Pass& pass = ws.passes[static_cast<size_t>(i)];
        if (!pass.enabled) continue;
        for (const Sampler& s : pass.samplers) {
            if (s.target.empty() || s.previousFrame || s.target == writes(i) || !ws.canReadTarget(s.target)) continue;
            bool earlier = false;
            std::vector<int> later;
            for (int j = 0; j < n; ++j) {
                if (!ws.passes[static_cast<size_t>(j)].enabled || writes(j) != s.target) continue;
                if (j < i) earlier = true;
                else if (j > i) later.push_back(j);
            }
            if (earlier) continue;
            if (later.empty()) {
                out.push_back({Diagnostic::Severity::Error, s.where, samplerLabel(s),
                               "pass '" + pass.name + "' reads target '" + s.target +
                                   "', which no pass writes (its contents would never change; to carry a target "
                                   "from frame to frame a pass must write it)"});
                continue;
            }
            // Is there a path from a later writer back to this pass? Then the passes form a cycle.
            std::vector<int> from(ws.passes.size(), -1);
            std::vector<std::string> via(ws.passes.size());
            std::deque<int> work;
            for (int q : later) {
                from[static_cast<size_t>(q)] = q;
                work.push_back(q);
            }
            bool cycle = false;
            while (!work.empty() && !cycle) {
                int x = work.front();
                work.pop_front();
                for (const Edge& e : edges[static_cast<size_t>(x)]) {
                    if (from[static_cast<size_t>(e.to)] != -1) continue;
                    from[static_cast<size_t>(e.to)] = x;
                    via[static_cast<size_t>(e.to)] = e.target;
                    if (e.to == i) {
                        cycle = true;
                        break;
                    }
                    work.push_back(e.to);
                }
            }
            if (cycle) {
                // Walk back from this pass to the later writer it started from.
                std::vector<int> path{i};
                for (int x = i; from[static_cast<size_t>(x)] != x;) {
                    x = from[static_cast<size_t>(x)];
                    path.push_back(x);
                }
                // path: i ← … ← q, read forwards as i reads from q … reads from i.
                std::string message = "passes form a cycle: '" + pass.name + "' reads '" + s.target + "' from '" +
                                      ws.passes[static_cast<size_t>(path.back())].name + "'";
                for (size_t k = path.size() - 1; k > 0; --k) {
                    int reader = path[k], writer = path[k - 1];
                    message += ", '" + ws.passes[static_cast<size_t>(reader)].name + "' reads '" +
                               via[static_cast<size_t>(writer)] + "' from '" + ws.passes[static_cast<size_t>(writer)].name + "'";
                }
                message += "; read one of them with frame=\"previous\" to take last frame's contents";
                out.push_back({Diagnostic::Severity::Error, s.where, samplerLabel(s), message});
            } else {
                out.push_back({Diagnostic::Severity::Error, s.where, samplerLabel(s),
                               "pass '" + pass.name + "' reads target '" + s.target +
                                   "' before any pass writes it in the frame ('" +
                                   ws.passes[static_cast<size_t>(later.front())].name +
                                   "' writes it later); move the pass after it, or read last frame's contents with "
                                   "frame=\"previous\""});
            }
        }
    }
    return out;
}

}  // namespace rmfx
