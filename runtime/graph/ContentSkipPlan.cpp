#include "graph/ContentSkipPlan.h"

#include <algorithm>

namespace rmfx {
namespace {

// Whether `pass` samples `target` as this frame leaves it (not frame="previous").
bool readsThisFrame(const Pass& pass, const std::string& target) {
    return std::any_of(pass.samplers.begin(), pass.samplers.end(),
                       [&](const Sampler& s) { return s.target == target && !s.previousFrame; });
}

bool isOutput(const std::vector<std::string>& outputs, const std::string& target) {
    return std::find(outputs.begin(), outputs.end(), target) != outputs.end();
}

struct Schedule {
    const Workspace& ws;
    const std::vector<int>& indices;

    size_t size() const { return indices.size(); }
    const Pass& pass(size_t position) const { return ws.passes[static_cast<size_t>(indices[position])]; }
    std::string target(size_t position) const { return ws.passTargetName(pass(position)); }
};

void planEffects(const Schedule& schedule, const std::vector<std::string>& outputs, ContentSkipPlan& plan) {
    const Workspace& ws = schedule.ws;
    for (const Effect& e : ws.effects) {
        if (e.source.empty() || !ws.canReadTarget(e.source)) continue;
        ContentSkipPlan::SkippableEffect active;
        active.effect = &e;
        std::vector<size_t> positions;
        std::set<std::string> written;
        for (size_t i = 0; i < schedule.size(); ++i) {
            if (!e.hasPass(schedule.pass(i).name)) continue;
            positions.push_back(i);
            written.insert(schedule.target(i));
        }
        if (positions.empty()) continue;
        // The gate is counted in its place where a scheduled pass writes it before the effect.
        ContentSkipPlan::Probe probe{e.source, e.sourceChannels};
        if (!e.gate.empty() && ws.canReadTarget(e.gate))
            for (size_t i = 0; i < positions.front(); ++i)
                if (schedule.target(i) == e.gate) {
                    probe = {e.gate, e.gateChannels};
                    active.gated = true;
                }
        // Asked for by name (an empty list, every target, is the editor's thumbnails): exact bits.
        const auto readBack = std::find_if(written.begin(), written.end(), [&](const std::string& t) { return isOutput(outputs, t); });
        if (readBack != written.end()) {
            plan.runningAlways[e.name] = "its target '" + *readBack + "' is read back after the frame, and holds what its passes write";
            continue;
        }
        active.first = positions.front();
        active.last = positions.back();
        const int self = static_cast<int>(plan.effects.size());
        for (size_t i : positions) plan.effectOfPass[i] = self;
        // Handed on: read by a scheduled pass outside the effect, or read back after the frame
        // (only where every target is: one asked for by name makes the effect run, above).
        for (const std::string& t : written) {
            ContentSkipPlan::HandedOn handed;
            handed.target = t;
            handed.readBack = outputs.empty();
            for (size_t i = 0; i < schedule.size(); ++i)
                if (plan.effectOfPass[i] != self && readsThisFrame(schedule.pass(i), t)) handed.readers.push_back(i);
            if (handed.readBack || !handed.readers.empty()) active.handedOn.push_back(std::move(handed));
        }
        auto shared = std::find_if(plan.probes.begin(), plan.probes.end(), [&](const ContentSkipPlan::Probe& p) {
            return p.source == probe.source && p.channels == probe.channels;
        });
        if (shared == plan.probes.end()) shared = plan.probes.insert(plan.probes.end(), probe);
        active.probe = static_cast<size_t>(shared - plan.probes.begin());
        plan.effects.push_back(std::move(active));
    }
}

void planFeeders(const Schedule& schedule, const std::vector<std::string>& outputs, ContentSkipPlan& plan) {
    if (plan.effects.empty() || outputs.empty()) return;  // every target is read back after the frame
    // Each probe reads its source before the first pass drawn under it: feeders come after the
    // source's last write.
    std::vector<size_t> sourceComplete(plan.probes.size(), 0);
    for (size_t p = 0; p < plan.probes.size(); ++p)
        for (size_t i = 0; i < schedule.size(); ++i)
            if (schedule.target(i) == plan.probes[p].source) sourceComplete[p] = i + 1;
    std::set<std::string> previousFrame, sources;
    for (size_t i = 0; i < schedule.size(); ++i)
        for (const Sampler& s : schedule.pass(i).samplers)
            if (s.previousFrame) previousFrame.insert(s.target);
    for (const ContentSkipPlan::Probe& p : plan.probes) sources.insert(p.source);
    // From the last pass back, so that a feeder's readers are decided before it.
    for (size_t i = schedule.size(); i-- > 0;) {
        if (plan.effectOfPass[i] >= 0) continue;
        const std::string written = schedule.target(i);
        if (isOutput(outputs, written) || previousFrame.count(written) || sources.count(written)) continue;
        int probe = -1;
        bool feeds = true, read = false;
        std::set<std::string> effects;
        for (size_t j = 0; j < schedule.size() && feeds; ++j) {
            if (j == i) continue;
            if (schedule.target(j) == written) {  // another pass writes it too
                feeds = false;
                continue;
            }
            // (What is read as last frame's was ruled out above.)
            if (!readsThisFrame(schedule.pass(j), written)) continue;
            read = true;
            const int readerProbe = plan.probeAt(j);
            feeds = j > i && readerProbe >= 0 && (probe < 0 || probe == readerProbe);
            probe = readerProbe;
            if (plan.effectOfPass[j] >= 0) effects.insert(plan.effects[static_cast<size_t>(plan.effectOfPass[j])].effect->name);
            for (const ContentSkipPlan::Feeder& f : plan.feeders)
                if (f.position == j) effects.insert(f.effects.begin(), f.effects.end());
        }
        if (!feeds || !read || i < sourceComplete[static_cast<size_t>(probe)]) continue;
        plan.feederProbe[i] = probe;
        plan.feeders.push_back({i, std::move(effects), static_cast<size_t>(probe)});
    }
    std::reverse(plan.feeders.begin(), plan.feeders.end());
}

void planConsumers(const Schedule& schedule, ContentSkipPlan& plan) {
    for (size_t i = 0; i < schedule.size(); ++i) {
        if (plan.probeAt(i) >= 0) continue;
        ContentSkipPlan::Consumer consumer{i, {}, 0};
        std::set<size_t> probes;
        for (const ContentSkipPlan::SkippableEffect& e : plan.effects) {
            if (i <= e.last) continue;
            if (std::none_of(e.handedOn.begin(), e.handedOn.end(),
                             [&](const ContentSkipPlan::HandedOn& h) { return readsThisFrame(schedule.pass(i), h.target); }))
                continue;
            consumer.effects.insert(e.effect->name);
            probes.insert(e.probe);
        }
        // One condition decides one draw: effects on different probes could be skipped apart.
        if (consumer.effects.empty() || probes.size() != 1) continue;
        consumer.probe = *probes.begin();
        plan.consumers.push_back(std::move(consumer));
    }
}

}  // namespace

int ContentSkipPlan::probeAt(size_t position) const {
    if (position < effectOfPass.size() && effectOfPass[position] >= 0)
        return static_cast<int>(effects[static_cast<size_t>(effectOfPass[position])].probe);
    return position < feederProbe.size() ? feederProbe[position] : -1;
}

bool ContentSkipPlan::endsAnEffect(size_t position) const {
    return std::any_of(effects.begin(), effects.end(), [&](const SkippableEffect& e) { return e.last == position; });
}

ContentSkipPlan planContentSkip(const Workspace& ws, const std::vector<int>& schedule, const std::vector<std::string>& outputs) {
    ContentSkipPlan plan;
    plan.effectOfPass.assign(schedule.size(), -1);
    plan.feederProbe.assign(schedule.size(), -1);
    const Schedule s{ws, schedule};
    planEffects(s, outputs, plan);
    planFeeders(s, outputs, plan);
    planConsumers(s, plan);
    return plan;
}

bool hasSourcedEffects(const Workspace& ws) {
    return std::any_of(ws.effects.begin(), ws.effects.end(), [](const Effect& e) { return !e.source.empty(); });
}

}  // namespace rmfx
