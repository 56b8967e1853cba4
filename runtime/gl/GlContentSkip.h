#pragma once
// Skipping on the GPU what an effect computes from a source that holds nothing (<effect source>):
// when no pixel of the source has a non-zero value in the chosen channels, every pass of the
// effect gives zero everywhere. Before the effect's first pass of a frame a probe draws over the
// source (a fragment for each 2x2 pixels) into a framebuffer with no attachment, discarding the
// fragments whose pixels' chosen channels are all zero, inside an occlusion query. The effect's
// passes then run under conditional rendering on that query (GL_QUERY_WAIT: the GPU waits for it,
// the CPU never does, and the frame uses its own source, with no frame of lag); after its last
// pass, under the inverted condition, the targets it hands to later passes (and those read back
// after the frame) are cleared to zero, which is what running it would have left there, unless
// what reads them is drawn compiled without the effect and samples none of them. A NaN or an
// infinity is not zero: the effect runs on it. An effect with a gate (<effect gate>) is decided by
// counting the gate, written before the source, in the same way; the source's passes are then
// feeders like any other.
// Passes outside the effects that only they read, between the source and the effects (hdr_lighting's
// star_source, the blur of the bright pass that bloom and star start from), are feeders: drawn
// under the same condition, since where it fails nothing reads what they write.
// The probe is flushed to the GPU at once, and each later pass under its condition asks whether
// the answer has arrived, without waiting: once it has, the CPU leaves the passes out itself (or
// draws them without a condition), which saves issuing them; until then the GPU decides.
// Needs a current GL 4.5 context.

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "core/Result.h"
#include "gl/GlHandles.h"
#include "gl/GlRenderTargets.h"
#include "gl/PassObserver.h"
#include "graph/ContentSkipPlan.h"
#include "graph/FramePlan.h"
#include "model/Workspace.h"

namespace rmfx {

struct GpuPass;

class GlContentSkip : public PassObserver {
public:
    static Result<std::unique_ptr<GlContentSkip>> create();

    // For a new schedule (the effect switches changed): its plan (graph/ContentSkipPlan.h), which
    // must outlive its use, with the targets it names found in `targets`. What the effects' last
    // frame skipped is forgotten.
    void usePlan(const ContentSkipPlan& plan, const GlRenderTargets& targets);
    const ContentSkipPlan& plan() const { return *plan_; }

    // Whether one conditional rendering may span consecutive passes of an effect (each pass's
    // begin and end cost the driver a wait on the query): not when something else draws between
    // passes that must run whatever the condition (the health check).
    void setSpanning(bool spanning) { spanning_ = spanning; }
    void setDecision(ContentSkipDecision decision) { decision_ = decision; }

    void beginFrame();
    // Around scheduled pass `index` (its position in the plan's schedule). beforePass returns
    // false when the CPU knows the pass is left out this frame: it is then not issued at all
    // (afterPass is still called).
    bool beforePass(size_t index);
    void afterPass(size_t index);
    // As an observer of the frame (gl/PassObserver.h): the same, around each scheduled pass.
    void beginFrame(int, size_t) override { beginFrame(); }
    bool beforePass(const ObservedPass& pass) override { return beforePass(pass.position); }
    void afterDraws(const ObservedPass& pass) override { afterPass(pass.position); }
    using PassObserver::afterPass;
    // How many passes of the last finished frame the CPU left out (beforePass false).
    int passesNotIssued() const { return lastNotIssued_; }
    // The query whose answer decides whether scheduled pass `index` is drawn this frame (between
    // beforePass and the end of the frame), for draws that look at what it wrote; 0: it is drawn
    // (or the CPU already knows it is).
    unsigned conditionOf(size_t index) const;
    void endFrame() override;

    // Around a consumer's draws (ContentSkipPlan::Consumer): `withoutEffects` false for the
    // program as compiled (drawn where the source holds something), true for the one without the
    // effects (where it holds nothing). Without an issued probe, the program as compiled is drawn
    // unconditionally and the other not at all: false when the draw is to be left out.
    bool beginConsumerDraw(size_t position, bool withoutEffects);
    void endConsumerDraw();
    // The targets each consumer's second program samples, by schedule position (none given: it has
    // no second program and draws as compiled). A target handed on only to second programs that do
    // not sample it, and not read back after the frame, is not cleared where its effect is
    // skipped: nothing reads the zeros. Replaces what an earlier call gave.
    void setSampledWithoutEffects(const std::map<size_t, std::set<const GpuTarget*>>& sampled);

    // The effects the last frame skipped, each with why; waits for the GPU's answer when `wait`,
    // else reports only what has arrived (and what arrived for an earlier frame is kept).
    const std::map<std::string, std::string>& skipped(bool wait);

private:
    enum class Answer { Pending, Nothing, Something };  // as far as the CPU knows this frame
    // The GL side of a plan's probe; kept across plans for the same source and channels.
    struct Probe {
        std::string source;
        glm::bvec4 channels{false};
        GpuTarget* target = nullptr;  // the source's (the executor's targets outlive every plan)
        QueryHandle queries[3];
        FenceHandle fence;    // after this frame's query (CpuWhenKnown): whether its answer is in
        bool issued = false;  // this frame
        Answer answer = Answer::Pending;
    };
    // A target a plan's effect hands on, found; cleared where the effect is skipped unless nothing
    // would read the zeros.
    struct HandedOnTarget {
        size_t effect = 0;  // into the plan's effects
        const ContentSkipPlan::HandedOn* handed = nullptr;
        GpuTarget* target = nullptr;
        bool cleared = true;
    };

    GlContentSkip() = default;
    void issueProbe(Probe& probe);
    // Asks the GPU without waiting (but with CpuWaits); ends a conditional rendering on the
    // probe's query before reading it.
    Answer answerOf(Probe& probe);
    void endCondition();
    Probe* probeAt(size_t index) const;  // the probe whose condition scheduled pass `index` is drawn under

    ProgramHandle program_;
    FramebufferHandle empty_;
    glm::ivec2 maxSize_{0, 0};    // the largest framebuffer
    glm::ivec2 emptySize_{0, 0};  // empty_'s default size
    SamplerHandle nearest_;
    VertexArrayHandle vertexArray_;
    int channelsLocation_ = -1;

    const ContentSkipPlan* plan_ = nullptr;
    std::vector<std::unique_ptr<Probe>> probes_;  // every probe some plan has used
    std::vector<Probe*> planProbes_;              // the plan's probes, by its index
    std::vector<HandedOnTarget> handedOn_;
    bool consumerCondition_ = false;
    int slot_ = 0;                   // the query of this frame in each probe's ring
    int lastFrameSlot_ = -1;         // the last finished frame's, -1 before the first
    bool spanning_ = true;
    ContentSkipDecision decision_ = ContentSkipDecision::CpuWhenKnown;
    Probe* condition_ = nullptr;     // the probe whose condition is active
    int notIssued_ = 0, lastNotIssued_ = 0;
    std::map<std::string, std::string> skipped_;
};

}  // namespace rmfx
