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

void GlContentSkip::usePlan(const ContentSkipPlan& plan, const GlRenderTargets& targets) {
    plan_ = &plan;
    skipped_.clear();
    lastFrameSlot_ = -1;
    planProbes_.clear();
    for (const ContentSkipPlan::Probe& wanted : plan.probes) {
        auto kept = std::find_if(probes_.begin(), probes_.end(), [&](const std::unique_ptr<Probe>& p) {
            return p->source == wanted.source && p->channels == wanted.channels;
        });
        if (kept == probes_.end()) {
            auto fresh = std::make_unique<Probe>();
            fresh->source = wanted.source;
            fresh->channels = wanted.channels;
            fresh->target = targets.find(wanted.source);
            for (QueryHandle& q : fresh->queries) q = createQuery(GL_ANY_SAMPLES_PASSED);
            kept = probes_.insert(probes_.end(), std::move(fresh));
        }
        planProbes_.push_back(kept->get());
    }
    handedOn_.clear();
    for (size_t e = 0; e < plan.effects.size(); ++e)
        for (const ContentSkipPlan::HandedOn& h : plan.effects[e].handedOn)
            if (GpuTarget* target = targets.find(h.target)) handedOn_.push_back({e, &h, target, true});
}

GlContentSkip::Probe* GlContentSkip::probeAt(size_t index) const {
    const int p = plan_ ? plan_->probeAt(index) : -1;
    return p < 0 ? nullptr : planProbes_[static_cast<size_t>(p)];
}

bool GlContentSkip::beginConsumerDraw(size_t position, bool withoutEffects) {
    for (const ContentSkipPlan::Consumer& consumer : plan_->consumers) {
        if (consumer.position != position) continue;
        Probe& probe = *planProbes_[consumer.probe];
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
    for (HandedOnTarget& h : handedOn_)
        h.cleared = h.handed->readBack || std::any_of(h.handed->readers.begin(), h.handed->readers.end(), [&](size_t reader) {
                        auto second = sampled.find(reader);
                        return second == sampled.end() || second->second.count(h.target);
                    });
}

void GlContentSkip::endConsumerDraw() {
    if (consumerCondition_) glEndConditionalRender();
    consumerCondition_ = false;
}

void GlContentSkip::beginFrame() {
    for (auto& p : probes_) {
        p->issued = false;
        p->answer = Answer::Pending;
        p->fence.reset();
    }
    condition_ = nullptr;
    notIssued_ = 0;
}

GlContentSkip::Answer GlContentSkip::answerOf(Probe& probe) {
    if (!probe.issued || probe.answer != Answer::Pending || decision_ == ContentSkipDecision::GpuOnly) return probe.answer;
    const bool waits = decision_ == ContentSkipDecision::CpuWaits;
    // The fence, not the query: NVIDIA reports GL_INVALID_OPERATION for reading a query that an
    // active conditional rendering uses (the passes spanned by the probe's condition ask here).
    if (!waits && !probe.fence.signalled()) return Answer::Pending;
    if (condition_ == &probe) endCondition();
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
    if (condition_) glEndConditionalRender();
    condition_ = nullptr;
}

void GlContentSkip::issueProbe(Probe& probe) {
    if (!probe.target || !probe.target->resource) return;
    const GpuTarget& t = *probe.target;
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
    if (decision_ == ContentSkipDecision::CpuWhenKnown) {
        probe.fence.insert();
        glFlush();
    }
}

bool GlContentSkip::beforePass(size_t index) {
    Probe* p = probeAt(index);
    if (!p) return true;
    Probe& probe = *p;
    if (!probe.issued) issueProbe(probe);
    if (!probe.issued) return true;
    const Answer answer = answerOf(probe);
    if (answer != Answer::Pending) {
        endCondition();
        if (answer == Answer::Nothing) ++notIssued_;
        return answer == Answer::Something;
    }
    if (condition_ == p) return true;
    glBeginConditionalRender(probe.queries[slot_].get(), GL_QUERY_WAIT);
    condition_ = p;
    return true;
}

unsigned GlContentSkip::conditionOf(size_t index) const {
    const Probe* p = probeAt(index);
    if (!p) return 0;
    const Probe& probe = *p;
    if (!probe.issued || probe.answer == Answer::Something) return 0;
    return probe.queries[slot_].get();
}

void GlContentSkip::afterPass(size_t index) {
    const Probe* p = probeAt(index);
    if (!p) return;
    const Probe& probe = *p;
    if (!probe.issued) return;
    // An effect's last pass ends the condition: what it hands on is cleared under the inverse.
    const bool ends = plan_->endsAnEffect(index);
    if (spanning_ && !ends && probeAt(index + 1) == p && condition_ == p) return;
    endCondition();
    if (!ends || probe.answer == Answer::Something) return;
    const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const bool conditional = probe.answer == Answer::Pending;
    if (conditional) glBeginConditionalRender(probe.queries[slot_].get(), GL_QUERY_WAIT_INVERTED);
    for (const HandedOnTarget& h : handedOn_)
        if (plan_->effects[h.effect].last == index && h.cleared && h.target->resource) {
            glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            glDisable(GL_SCISSOR_TEST);
            glClearNamedFramebufferfv(h.target->resource->framebuffers[h.target->resource->writeBuffer()].get(), GL_COLOR, 0, zero);
        }
    if (conditional) glEndConditionalRender();
    for (const HandedOnTarget& h : handedOn_)
        if (plan_->effects[h.effect].last == index && h.cleared && h.target->resource && h.target->resource->spec.mipmaps)
            glGenerateTextureMipmap(h.target->resource->textures[h.target->resource->writeBuffer()].get());
}

void GlContentSkip::endFrame() {
    lastNotIssued_ = notIssued_;
    if (!plan_ || plan_->empty()) return;
    lastFrameSlot_ = slot_;
    slot_ = (slot_ + 1) % 3;
}

const std::map<std::string, std::string>& GlContentSkip::skipped(bool wait) {
    if (lastFrameSlot_ < 0) return skipped_;
    for (const ContentSkipPlan::SkippableEffect& e : plan_->effects) {
        const Probe& probe = *planProbes_[e.probe];
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
