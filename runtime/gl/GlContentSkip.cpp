#include "gl/GlContentSkip.h"

#include <algorithm>

#include <epoxy/gl.h>

#include "gl/GlFullScreenTriangle.h"
#include "gl/GpuPass.h"

namespace rmfx {
namespace {

// A fragment passes (and counts) when one of the chosen channels of one of its 2x2 pixels is not
// exactly zero; NaN is not. A quarter of the fragments, the same fetches: on llvmpipe the probe
// costs about 1 % of a dark hdr_lighting frame with a fragment a pixel. At an odd size the last
// column or row is fetched twice, which changes no answer.
const char* const probeFragment = R"(#version 450 core
uniform sampler2D Source;
uniform bvec4 Channels;
void main() {
    ivec2 last = textureSize(Source, 0) - 1;
    ivec2 p = 2 * ivec2(gl_FragCoord.xy);
    uvec4 nonZero = uvec4(0u);
    for (int i = 0; i < 4; ++i)
        nonZero |= uvec4(notEqual(texelFetch(Source, min(p + ivec2(i & 1, i >> 1), last), 0), vec4(0.0)));
    if (!any(bvec4(nonZero & uvec4(Channels))))
        discard;
}
)";

std::string compileStage(GLuint shader, const char* source) {
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok) return "";
    char log[1024] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    return log;
}

// Whether `pass` samples `target` as this frame leaves it (not frame="previous").
bool readsThisFrame(const Pass& pass, const std::string& target) {
    return std::any_of(pass.samplers.begin(), pass.samplers.end(),
                       [&](const Sampler& s) { return s.target == target && !s.previousFrame; });
}

std::string channelNames(glm::bvec4 channels) {
    static const char* const names[4] = {"red", "green", "blue", "alpha"};
    std::vector<std::string> chosen;
    for (int c = 0; c < 4; ++c)
        if (channels[c]) chosen.push_back(names[c]);
    std::string out;
    for (size_t i = 0; i < chosen.size(); ++i)
        out += (i == 0 ? "" : i + 1 == chosen.size() ? " or " : ", ") + chosen[i];
    return out;
}

}  // namespace

Result<std::unique_ptr<GlContentSkip>> GlContentSkip::create() {
    std::unique_ptr<GlContentSkip> skip(new GlContentSkip);
    ShaderHandle vs = createShader(GL_VERTEX_SHADER), fs = createShader(GL_FRAGMENT_SHADER);
    if (std::string e = compileStage(vs.get(), fullScreenTriangleVertexSource()); !e.empty()) return Error{"content-skip probe: " + e};
    if (std::string e = compileStage(fs.get(), probeFragment); !e.empty()) return Error{"content-skip probe: " + e};
    skip->program_ = createProgram();
    glAttachShader(skip->program_.get(), vs.get());
    glAttachShader(skip->program_.get(), fs.get());
    glLinkProgram(skip->program_.get());
    GLint linked = 0;
    glGetProgramiv(skip->program_.get(), GL_LINK_STATUS, &linked);
    if (!linked) return Error{"content-skip probe: the program does not link"};
    skip->channelsLocation_ = glGetUniformLocation(skip->program_.get(), "Channels");
    glProgramUniform1i(skip->program_.get(), glGetUniformLocation(skip->program_.get(), "Source"), 0);
    skip->empty_ = createFramebuffer();
    glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &skip->maxSize_.x);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &skip->maxSize_.y);
    skip->nearest_ = createSampler();
    glSamplerParameteri(skip->nearest_.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(skip->nearest_.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    skip->vertexArray_ = createVertexArray();
    return skip;
}

void GlContentSkip::plan(const Workspace& ws, const std::vector<GpuPass*>& schedule, const GlRenderTargets& targets,
                         const std::vector<std::string>& outputs) {
    effects_.clear();
    skipped_.clear();
    runningAlways_.clear();
    lastFrameSlot_ = -1;
    effectOfPass_.assign(schedule.size(), -1);
    for (const Effect& e : ws.effects) {
        GpuTarget* source = e.source.empty() ? nullptr : targets.find(e.source);
        if (!source) continue;
        ActiveEffect active;
        active.effect = &e;
        std::vector<size_t> positions;
        std::set<std::string> written;
        for (size_t i = 0; i < schedule.size(); ++i) {
            const std::string& pass = schedule[i]->pass->name;
            if (!e.hasPass(pass)) continue;
            positions.push_back(i);
            written.insert(schedule[i]->target->name);
        }
        if (positions.empty()) continue;
        // The gate is counted in its place where a scheduled pass writes it before the effect.
        glm::bvec4 channels = e.sourceChannels;
        GpuTarget* gate = e.gate.empty() ? nullptr : targets.find(e.gate);
        if (gate && std::any_of(schedule.begin(), schedule.begin() + static_cast<std::ptrdiff_t>(positions.front()),
                                [&](const GpuPass* p) { return p->target == gate; })) {
            source = gate;
            channels = e.gateChannels;
            active.gated = true;
        }
        // Asked for by name (an empty list, every target, is the editor's thumbnails): exact bits.
        const auto readBack = std::find_if(written.begin(), written.end(), [&](const std::string& t) {
            return std::find(outputs.begin(), outputs.end(), t) != outputs.end();
        });
        if (readBack != written.end()) {
            runningAlways_[e.name] = "its target '" + *readBack + "' is read back after the frame, and holds what its passes write";
            continue;
        }
        active.first = positions.front();
        active.last = positions.back();
        for (size_t i : positions) effectOfPass_[i] = static_cast<int>(effects_.size());
        // Handed on: read by a scheduled pass outside the effect, or read back after the frame
        // (only where every target is: one asked for by name makes the effect run, above).
        for (const std::string& t : written) {
            HandedOn handed;
            handed.target = targets.find(t);
            handed.readBack = outputs.empty();
            for (size_t i = 0; i < schedule.size(); ++i)
                if (effectOfPass_[i] != static_cast<int>(effects_.size()) && readsThisFrame(*schedule[i]->pass, t))
                    handed.readers.push_back(i);
            if (handed.target && (handed.readBack || !handed.readers.empty())) active.handedOn.push_back(std::move(handed));
        }
        auto probe = std::find_if(probes_.begin(), probes_.end(), [&](const Probe& p) {
            return p.source == source && p.channels == channels;
        });
        if (probe == probes_.end()) {
            Probe fresh;
            fresh.source = source;
            fresh.channels = channels;
            for (QueryHandle& q : fresh.queries) q = createQuery(GL_ANY_SAMPLES_PASSED);
            probes_.push_back(std::move(fresh));
            probe = probes_.end() - 1;
        }
        active.probe = static_cast<size_t>(probe - probes_.begin());
        effects_.push_back(std::move(active));
    }
    planFeeders(schedule, outputs);
    planConsumers(schedule);
}

void GlContentSkip::planFeeders(const std::vector<GpuPass*>& schedule, const std::vector<std::string>& outputs) {
    feeders_.clear();
    feederProbe_.assign(schedule.size(), -1);
    if (effects_.empty() || outputs.empty()) return;  // every target is read back after the frame
    // Each probe reads its source before the first pass drawn under it: feeders come after the
    // source's last write.
    std::vector<size_t> sourceComplete(probes_.size(), 0);
    for (size_t p = 0; p < probes_.size(); ++p)
        for (size_t i = 0; i < schedule.size(); ++i)
            if (schedule[i]->target == probes_[p].source) sourceComplete[p] = i + 1;
    std::set<std::string> previousFrame, sources;
    for (const GpuPass* gp : schedule)
        for (const Sampler& s : gp->pass->samplers)
            if (s.previousFrame) previousFrame.insert(s.target);
    for (const Probe& p : probes_) sources.insert(p.source->name);
    // From the last pass back, so that a feeder's readers are decided before it.
    for (size_t i = schedule.size(); i-- > 0;) {
        if (effectOfPass_[i] >= 0) continue;
        const std::string& written = schedule[i]->target->name;
        if (std::find(outputs.begin(), outputs.end(), written) != outputs.end() || previousFrame.count(written) ||
            sources.count(written))
            continue;
        int probe = -1;
        bool feeds = true, read = false;
        std::set<std::string> effects;
        for (size_t j = 0; j < schedule.size() && feeds; ++j) {
            if (j == i) continue;
            if (schedule[j]->target->name == written) {  // another pass writes it too
                feeds = false;
                continue;
            }
            // (What is read as last frame's was ruled out above.)
            if (!readsThisFrame(*schedule[j]->pass, written)) continue;
            read = true;
            const int readerProbe = probeAt(j);
            feeds = j > i && readerProbe >= 0 && (probe < 0 || probe == readerProbe);
            probe = readerProbe;
            if (effectOfPass_[j] >= 0) effects.insert(effects_[static_cast<size_t>(effectOfPass_[j])].effect->name);
            for (const Feeder& f : feeders_)
                if (f.position == j) effects.insert(f.effects.begin(), f.effects.end());
        }
        if (!feeds || !read || i < sourceComplete[static_cast<size_t>(probe)]) continue;
        feederProbe_[i] = probe;
        feeders_.push_back({i, std::move(effects), static_cast<size_t>(probe)});
    }
    std::reverse(feeders_.begin(), feeders_.end());
}

int GlContentSkip::probeAt(size_t index) const {
    if (index < effectOfPass_.size() && effectOfPass_[index] >= 0)
        return static_cast<int>(effects_[static_cast<size_t>(effectOfPass_[index])].probe);
    return index < feederProbe_.size() ? feederProbe_[index] : -1;
}

bool GlContentSkip::endsAnEffect(size_t index) const {
    return std::any_of(effects_.begin(), effects_.end(), [&](const ActiveEffect& e) { return e.last == index; });
}

void GlContentSkip::planConsumers(const std::vector<GpuPass*>& schedule) {
    consumers_.clear();
    for (size_t i = 0; i < schedule.size(); ++i) {
        if (probeAt(i) >= 0) continue;
        Consumer consumer{i, {}, 0};
        std::set<size_t> probes;
        for (const ActiveEffect& e : effects_) {
            if (i <= e.last) continue;
            if (std::none_of(e.handedOn.begin(), e.handedOn.end(),
                             [&](const HandedOn& h) { return readsThisFrame(*schedule[i]->pass, h.target->name); }))
                continue;
            consumer.effects.insert(e.effect->name);
            probes.insert(e.probe);
        }
        // One condition decides one draw: effects on different probes could be skipped apart.
        if (consumer.effects.empty() || probes.size() != 1) continue;
        consumer.probe = *probes.begin();
        consumers_.push_back(std::move(consumer));
    }
}

bool GlContentSkip::beginConsumerDraw(size_t position, bool withoutEffects) {
    for (const Consumer& consumer : consumers_) {
        if (consumer.position != position) continue;
        Probe& probe = probes_[consumer.probe];
        if (!probe.issued) return !withoutEffects;
        switch (answerOf(probe)) {
            case Answer::Nothing: return withoutEffects;
            case Answer::Something: return !withoutEffects;
            case Answer::Pending: break;
        }
        glBeginConditionalRender(probe.queries[slot_].get(), withoutEffects ? GL_QUERY_WAIT_INVERTED : GL_QUERY_WAIT);
        consumerCondition_ = true;
        return true;
    }
    return !withoutEffects;
}

void GlContentSkip::setSampledWithoutEffects(const std::map<size_t, std::set<const GpuTarget*>>& sampled) {
    for (ActiveEffect& e : effects_)
        for (HandedOn& h : e.handedOn)
            h.cleared = h.readBack || std::any_of(h.readers.begin(), h.readers.end(), [&](size_t reader) {
                            auto second = sampled.find(reader);
                            return second == sampled.end() || second->second.count(h.target);
                        });
}

void GlContentSkip::endConsumerDraw() {
    if (consumerCondition_) glEndConditionalRender();
    consumerCondition_ = false;
}

void GlContentSkip::beginFrame() {
    for (Probe& p : probes_) {
        p.issued = false;
        p.answer = Answer::Pending;
        p.fence.reset();
    }
    conditionOf_ = -1;
    notIssued_ = 0;
}

GlContentSkip::Answer GlContentSkip::answerOf(Probe& probe) {
    if (!probe.issued || probe.answer != Answer::Pending || decision_ == FramePlanOptions::ContentSkipDecision::GpuOnly)
        return probe.answer;
    const bool waits = decision_ == FramePlanOptions::ContentSkipDecision::CpuWaits;
    // The fence, not the query: NVIDIA reports GL_INVALID_OPERATION for reading a query that an
    // active conditional rendering uses (the passes spanned by the probe's condition ask here).
    if (!waits && !probe.fence.signalled()) return Answer::Pending;
    if (conditionOf_ >= 0 && &probes_[static_cast<size_t>(conditionOf_)] == &probe) endCondition();
    const GLuint query = probe.queries[slot_].get();
    GLuint available = waits ? 1 : 0;
    if (!available) glGetQueryObjectuiv(query, GL_QUERY_RESULT_AVAILABLE, &available);
    if (!available) return Answer::Pending;
    GLuint passed = 1;
    glGetQueryObjectuiv(query, GL_QUERY_RESULT, &passed);
    probe.answer = passed ? Answer::Something : Answer::Nothing;
    probe.fence.reset();
    return probe.answer;
}

void GlContentSkip::endCondition() {
    if (conditionOf_ >= 0) glEndConditionalRender();
    conditionOf_ = -1;
}

void GlContentSkip::issueProbe(Probe& probe) {
    const GpuTarget& t = *probe.source;
    if (!t.resource) return;
    const GpuResource& r = *t.resource;
    const GLuint texture = r.textures[t.writtenThisFrame ? r.writeBuffer() : r.front].get();
    const glm::ivec2 size = (r.spec.size + 1) / 2;  // a fragment for each 2x2 pixels
    if (size.x > maxSize_.x || size.y > maxSize_.y) return;  // the effect then runs unconditionally
    if (size != emptySize_) {  // each change makes the driver validate the framebuffer again
        glNamedFramebufferParameteri(empty_.get(), GL_FRAMEBUFFER_DEFAULT_WIDTH, size.x);
        glNamedFramebufferParameteri(empty_.get(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, size.y);
        emptySize_ = size;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, empty_.get());
    glViewport(0, 0, size.x, size.y);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glUseProgram(program_.get());
    glProgramUniform4i(program_.get(), channelsLocation_, probe.channels.x, probe.channels.y, probe.channels.z,
                       probe.channels.w);
    glBindTextureUnit(0, texture);
    glBindSampler(0, nearest_.get());
    glBindVertexArray(vertexArray_.get());
    glBeginQuery(GL_ANY_SAMPLES_PASSED, probe.queries[slot_].get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEndQuery(GL_ANY_SAMPLES_PASSED);
    glBindVertexArray(0);
    glBindSampler(0, 0);
    probe.issued = true;
    // Sent now, so that the answer may be in before the passes it decides are issued.
    if (decision_ == FramePlanOptions::ContentSkipDecision::CpuWhenKnown) {
        probe.fence.insert();
        glFlush();
    }
}

bool GlContentSkip::beforePass(size_t index) {
    const int p = probeAt(index);
    if (p < 0) return true;
    Probe& probe = probes_[static_cast<size_t>(p)];
    if (!probe.issued) issueProbe(probe);
    if (!probe.issued) return true;
    const Answer answer = answerOf(probe);
    if (answer != Answer::Pending) {
        endCondition();
        if (answer == Answer::Nothing) ++notIssued_;
        return answer == Answer::Something;
    }
    if (conditionOf_ == p) return true;
    glBeginConditionalRender(probe.queries[slot_].get(), GL_QUERY_WAIT);
    conditionOf_ = p;
    return true;
}

unsigned GlContentSkip::conditionOf(size_t index) const {
    const int p = probeAt(index);
    if (p < 0) return 0;
    const Probe& probe = probes_[static_cast<size_t>(p)];
    if (!probe.issued || probe.answer == Answer::Something) return 0;
    return probe.queries[slot_].get();
}

void GlContentSkip::afterPass(size_t index) {
    const int p = probeAt(index);
    if (p < 0) return;
    const Probe& probe = probes_[static_cast<size_t>(p)];
    if (!probe.issued) return;
    // An effect's last pass ends the condition: what it hands on is cleared under the inverse.
    const bool ends = endsAnEffect(index);
    if (spanning_ && !ends && probeAt(index + 1) == p && conditionOf_ == p) return;
    endCondition();
    if (!ends || probe.answer == Answer::Something) return;
    const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const bool conditional = probe.answer == Answer::Pending;
    if (conditional) glBeginConditionalRender(probe.queries[slot_].get(), GL_QUERY_WAIT_INVERTED);
    for (const ActiveEffect& e : effects_) {
        if (e.last != index) continue;
        for (const HandedOn& h : e.handedOn)
            if (h.cleared && h.target->resource) {
                glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
                glDisable(GL_SCISSOR_TEST);
                glClearNamedFramebufferfv(h.target->resource->framebuffers[h.target->resource->writeBuffer()].get(), GL_COLOR, 0,
                                          zero);
            }
    }
    if (conditional) glEndConditionalRender();
    for (const ActiveEffect& e : effects_) {
        if (e.last != index) continue;
        for (const HandedOn& h : e.handedOn)
            if (h.cleared && h.target->resource && h.target->resource->spec.mipmaps)
                glGenerateTextureMipmap(h.target->resource->textures[h.target->resource->writeBuffer()].get());
    }
}

void GlContentSkip::endFrame() {
    lastNotIssued_ = notIssued_;
    if (effects_.empty()) return;
    lastFrameSlot_ = slot_;
    slot_ = (slot_ + 1) % 3;
}

const std::map<std::string, std::string>& GlContentSkip::skipped(bool wait) {
    if (lastFrameSlot_ < 0) return skipped_;
    for (const ActiveEffect& e : effects_) {
        const Probe& probe = probes_[e.probe];
        const GLuint query = probe.queries[lastFrameSlot_].get();
        GLuint available = 0;
        if (!wait) glGetQueryObjectuiv(query, GL_QUERY_RESULT_AVAILABLE, &available);
        if (!wait && !available) continue;
        GLuint passed = 1;
        glGetQueryObjectuiv(query, GL_QUERY_RESULT, &passed);
        if (passed)
            skipped_.erase(e.effect->name);
        else if (e.gated)
            skipped_[e.effect->name] = "its gate '" + e.effect->gate + "' holds no pixel with a non-zero " +
                                       channelNames(e.effect->gateChannels) + " value, so its source '" + e.effect->source +
                                       "' holds none either";
        else
            skipped_[e.effect->name] = "'" + e.effect->source + "' holds no pixel with a non-zero " +
                                       channelNames(e.effect->sourceChannels) + " value";
    }
    return skipped_;
}

}  // namespace rmfx
