// What the executor holds and what its last frame did: targets read back, the plan and the
// current switches, per-pass timing, health and content skip's reports (gl/GlExecutor.h).

#include <epoxy/gl.h>

#include "gl/GlErrors.h"
#include "gl/GlExecutorImpl.h"
#include "gl/GlFormats.h"
#include "gl/GlRenderState.h"

namespace rmfx {
namespace {

int lastWriter(const Workspace& ws, const std::string& target) {
    for (int i = static_cast<int>(ws.passes.size()) - 1; i >= 0; --i)
        if (ws.passes[static_cast<size_t>(i)].enabled && ws.passTargetName(ws.passes[static_cast<size_t>(i)]) == target) return i;
    return -1;
}

}  // namespace

void GlExecutor::setTimingEnabled(bool enabled) { impl_->timers.setEnabled(enabled); }
const std::vector<PassTiming>& GlExecutor::passTimings() const { return impl_->timers.timings(); }
double GlExecutor::frameGpuMilliseconds() const { return impl_->timers.frameMilliseconds(); }

const Value* GlExecutor::variable(const std::string& name) const {
    auto it = impl_->values.find(name);
    return it == impl_->values.end() ? nullptr : &it->second;
}

Result<Image> GlExecutor::readTarget(const std::string& name) const {
    const Impl& s = *impl_;
    const GpuTarget* t = s.targets.find(name);
    if (!t) return Error{"no render target named '" + name + "'"};
    const TargetPlan& plan = s.plan.targets;
    const PlannedTarget& planned = plan.targets[static_cast<size_t>(plan.find(name))];
    if (!t->resource) {
        std::string why = "target '" + name + "' is not computed: no pass the outputs need writes or reads it";
        if (int writer = lastWriter(s.ws, name); writer >= 0) {
            const PassNode& node = s.current.graph->nodes[static_cast<size_t>(writer)];
            why += " (its writer '" + s.ws.passes[static_cast<size_t>(writer)].name + "' is " + passFateName(node.fate) +
                   ": " + node.why + ")";
        }
        return Error{why + "; ask for it as an output (rmfx render --target " + name + ")"};
    }
    const GpuResource& r = *t->resource;
    if (static_cast<size_t>(r.spec.targets.back()) != static_cast<size_t>(plan.find(name)))
        return Error{"target '" + name + "' shares memory with '" + plan.targets[static_cast<size_t>(r.spec.targets.back())].name +
                     "', which overwrites it later in the frame; ask for it as an output (rmfx render --target " + name +
                     ") to keep it"};
    Image image;
    image.width = planned.size.x;
    image.height = planned.size.y;
    image.channels = gl::channelCount(planned.format) == 1 ? 1 : 4;
    image.highDynamicRange = true;
    std::vector<float> rgba(static_cast<size_t>(image.width) * image.height * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(r.textures[r.front].get(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(rgba.size() * sizeof(float)),
                      rgba.data());  // the newest finished contents
    if (std::string e = firstGlError(); !e.empty()) return Error{e + " reading target '" + name + "'"};
    image.pixels.resize(static_cast<size_t>(image.width) * image.height * image.channels);
    // GL's row 0 is the picture's bottom row, or its top row in a Direct3D texture space.
    const bool topFirst = rowsTopFirst(s.ws.textureSpace);
    for (int y = 0; y < image.height; ++y) {
        const float* src = &rgba[static_cast<size_t>(topFirst ? y : image.height - 1 - y) * image.width * 4];
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < image.channels; ++c) image.at(x, y, c) = src[x * 4 + c];
    }
    return image;
}

std::vector<std::string> GlExecutor::targetNames() const {
    std::vector<std::string> names;
    for (auto& t : impl_->targets.targets()) names.push_back(t->name);
    return names;
}

glm::ivec2 GlExecutor::targetSize(const std::string& name) const {
    const TargetPlan& plan = impl_->plan.targets;
    int i = plan.find(name);
    return i < 0 ? glm::ivec2(0) : plan.targets[static_cast<size_t>(i)].size;
}

TargetFormat GlExecutor::targetFormat(const std::string& name) const {
    const TargetPlan& plan = impl_->plan.targets;
    int i = plan.find(name);
    return i < 0 ? TargetFormat::RGBA8 : plan.targets[static_cast<size_t>(i)].format;
}

unsigned GlExecutor::targetTexture(const std::string& name) const {
    const GpuTarget* t = impl_->targets.find(name);
    return t && t->resource ? t->resource->textures[t->resource->front].get() : 0;
}

const Workspace& GlExecutor::workspace() const { return impl_->ws; }
const CompiledFrame& GlExecutor::compiledFrame() const { return *impl_->compiled; }
const FramePlan& GlExecutor::framePlan() const { return impl_->plan; }
const PassGraph& GlExecutor::graph() const { return *impl_->current.graph; }
const TargetPlan& GlExecutor::targetPlan() const { return impl_->plan.targets; }
const std::set<std::string>& GlExecutor::askedEffects() const { return impl_->plan.askedEffects; }
const std::set<std::string>& GlExecutor::switchedOffEffects() const { return impl_->current.switchedOff; }
const std::vector<std::string>& GlExecutor::passesRun() const { return impl_->lastFramePasses; }

const FrameHealth* GlExecutor::frameHealth(bool wait) {
    impl_->takeHealth(wait);
    return impl_->lastHealth ? &*impl_->lastHealth : nullptr;
}
const std::vector<HealthFinding>& GlExecutor::firstHealthFindings() {
    impl_->takeHealth(true);
    return impl_->firstFindings;
}

std::map<std::string, std::set<std::string>> GlExecutor::passesDrawnWithoutSkippedEffects() const {
    const Impl& s = *impl_;
    if (!s.contentSkip) return {};
    return s.compiled->passesDrawnWithoutSkippedEffects(s.current.switchedOff);
}

std::map<std::string, std::set<std::string>> GlExecutor::passesDrawnOnlyForEffects() const {
    const Impl& s = *impl_;
    if (!s.contentSkip) return {};
    return s.compiled->passesDrawnOnlyForEffects(s.current.switchedOff);
}

std::map<std::string, std::string> GlExecutor::effectsRunningWhateverTheContent() const {
    const Impl& s = *impl_;
    if (!s.contentSkip) return {};
    return s.compiled->effectsRunningWhateverTheContent(s.current.switchedOff);
}

int GlExecutor::passesNotIssuedByContentSkip() const {
    return impl_->contentSkip ? impl_->contentSkip->passesNotIssued() : 0;
}

const std::map<std::string, std::string>& GlExecutor::contentSkippedEffects(bool wait) {
    static const std::map<std::string, std::string> none;
    return impl_->contentSkip ? impl_->contentSkip->skipped(wait) : none;
}

}  // namespace rmfx
