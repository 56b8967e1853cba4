#include "gl/GlHealthObserver.h"

#include <utility>

namespace rmfx {

GlHealthObserver::GlHealthObserver(GlHealthCheck& check, const GlContentSkip* contentSkip,
                                   std::function<std::optional<std::string>(const SamplerSlot&)> inputLabel,
                                   std::function<bool(const GpuPass&)> keepsEarlierPixels)
    : check_(check), contentSkip_(contentSkip), inputLabel_(std::move(inputLabel)), keepsEarlierPixels_(std::move(keepsEarlierPixels)) {}

bool GlHealthObserver::beforePass(const ObservedPass& pass) {
    // Before the pass's condition: the inspections this flushes are of earlier passes.
    check_.beforeWriting(pass.writeTexture);
    inputs_.clear();
    return true;
}

void GlHealthObserver::samplerBound(const SamplerSlot& slot, unsigned texture) {
    if (std::optional<std::string> label = inputLabel_(slot)) inputs_.push_back({slot.sampler->uniform, std::move(*label), texture, slot.unit});
}

void GlHealthObserver::beforeDraw(const ObservedPass& pass, const GpuPass& program) {
    if (!program.health.found) return;
    // In the order its shader records them.
    std::vector<GlHealthCheck::Input> recorded;
    for (const std::string& sampler : program.healthInputs)
        for (const GlHealthCheck::Input& input : inputs_)
            if (input.sampler == sampler) recorded.push_back(input);
    const GpuPass& gp = *pass.scheduled;
    const TargetResource& memory = gp.target->resource->spec;
    check_.beforeCountingPass(pass.position, gp.pass->name, gp.target->name, memory.size, memory.format, recorded, program.health,
                              keepsEarlierPixels_(gp));
}

void GlHealthObserver::afterPass(const ObservedPass& pass, bool issued) {
    const GpuPass& gp = *pass.scheduled;
    // A pass that counted its own writes needs no inspection; one left out on the CPU is reported
    // clean: its inspection is drawn under the failed condition.
    if (issued && gp.health.found) return;
    const TargetResource& memory = gp.target->resource->spec;
    check_.afterPass(pass.position, gp.pass->name, gp.target->name, pass.writeTexture, memory.size, memory.format, inputs_,
                     gp.whyNotCounting, contentSkip_ ? contentSkip_->conditionOf(pass.position) : 0);
}

}  // namespace rmfx
