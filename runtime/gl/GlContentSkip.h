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
#include "graph/FramePlan.h"
#include "model/Workspace.h"

namespace rmfx {

struct GpuPass;

class GlContentSkip {
public:
    static Result<std::unique_ptr<GlContentSkip>> create();

    // For a new schedule (the effect switches changed): which of its passes belong to an effect
    // with a source, where each such effect starts and ends, and what it hands on. `outputs`: the
    // targets read after the frame (empty: every target).
    void plan(const Workspace& ws, const std::vector<GpuPass*>& schedule, const GlRenderTargets& targets,
              const std::vector<std::string>& outputs);

    // Whether one conditional rendering may span consecutive passes of an effect (each pass's
    // begin and end cost the driver a wait on the query): not when something else draws between
    // passes that must run whatever the condition (the health check).
    void setSpanning(bool spanning) { spanning_ = spanning; }
    void setDecision(FramePlanOptions::ContentSkipDecision decision) { decision_ = decision; }

    void beginFrame();
    // Around scheduled pass `index` (its position in the schedule given to plan()). beforePass
    // returns false when the CPU knows the pass is left out this frame: it is then not issued at
    // all (afterPass is still called).
    bool beforePass(size_t index);
    void afterPass(size_t index);
    // How many passes of the last finished frame the CPU left out (beforePass false).
    int passesNotIssued() const { return lastNotIssued_; }
    // The query whose answer decides whether scheduled pass `index` is drawn this frame (between
    // beforePass and the end of the frame), for draws that look at what it wrote; 0: it is drawn
    // (or the CPU already knows it is).
    unsigned conditionOf(size_t index) const;
    void endFrame();

    // A pass outside the effects that reads what effects sharing one probe hand on (hdr_lighting's
    // final, after bloom and star): where the probe finds nothing it can be drawn compiled with
    // those effects left out (their RMFX_EFFECT_* false), reading none of the cleared targets,
    // and as compiled where it finds something. Set by plan().
    struct Consumer {
        size_t position = 0;            // in the schedule
        std::set<std::string> effects;  // left out of the second program
        size_t probe = 0;               // the one their sources share
    };
    const std::vector<Consumer>& consumers() const { return consumers_; }

    // A pass outside the effects whose target only passes drawn under one probe's condition read
    // (effect passes, or other feeders), written after the source is complete and read back by
    // nothing after the frame: it is drawn under that condition too. Set by plan().
    struct Feeder {
        size_t position = 0;            // in the schedule
        std::set<std::string> effects;  // the effects that read it, directly or through other feeders
        size_t probe = 0;
    };
    const std::vector<Feeder>& feeders() const { return feeders_; }
    // Around a consumer's draws: `withoutEffects` false for the program as compiled (drawn where
    // the source holds something), true for the one without the effects (where it holds nothing).
    // Without an issued probe, the program as compiled is drawn unconditionally and the other not
    // at all: false when the draw is to be left out.
    bool beginConsumerDraw(size_t position, bool withoutEffects);
    void endConsumerDraw();
    // The targets each consumer's second program samples, by schedule position (none given: it has
    // no second program and draws as compiled). A target handed on only to second programs that do
    // not sample it, and not read back after the frame, is not cleared where its effect is
    // skipped: nothing reads the zeros. Replaces what an earlier call gave.
    void setSampledWithoutEffects(const std::map<size_t, std::set<const GpuTarget*>>& sampled);

    // The effects with a source that content skip leaves running whatever it holds, each with why
    // (a target it writes is read back after the frame, and must hold what its passes write, not
    // zeros: running a pass on a zero source can still write a non-zero alpha). Set by plan().
    const std::map<std::string, std::string>& runningAlways() const { return runningAlways_; }

    // The effects the last frame skipped, each with why; waits for the GPU's answer when `wait`,
    // else reports only what has arrived (and what arrived for an earlier frame is kept).
    const std::map<std::string, std::string>& skipped(bool wait);

private:
    enum class Answer { Pending, Nothing, Something };  // as far as the CPU knows this frame
    struct Probe {
        GpuTarget* source = nullptr;
        glm::bvec4 channels{false};
        QueryHandle queries[3];
        FenceHandle fence;    // after this frame's query (CpuWhenKnown): whether its answer is in
        bool issued = false;  // this frame
        Answer answer = Answer::Pending;
    };
    // A target the effect writes that something after it reads: cleared to zero when the effect is
    // skipped, unless nothing would read the zeros.
    struct HandedOn {
        GpuTarget* target = nullptr;
        bool readBack = false;        // after the frame (the editor reads every target)
        std::vector<size_t> readers;  // schedule positions of the passes outside the effect that sample it
        bool cleared = true;
    };
    struct ActiveEffect {
        const Effect* effect = nullptr;
        size_t probe = 0;
        bool gated = false;                   // the probe counts its gate, not its source
        size_t first = 0, last = 0;           // schedule positions of its first and last pass
        std::vector<HandedOn> handedOn;
    };

    GlContentSkip() = default;
    void issueProbe(Probe& probe);
    // Asks the GPU without waiting (but with CpuWaits); ends a conditional rendering on the
    // probe's query before reading it.
    Answer answerOf(Probe& probe);
    void endCondition();
    void planFeeders(const std::vector<GpuPass*>& schedule, const std::vector<std::string>& outputs);
    void planConsumers(const std::vector<GpuPass*>& schedule);
    int probeAt(size_t index) const;  // the probe whose condition scheduled pass `index` is drawn under, or -1
    bool endsAnEffect(size_t index) const;

    ProgramHandle program_;
    FramebufferHandle empty_;
    glm::ivec2 maxSize_{0, 0};    // the largest framebuffer
    glm::ivec2 emptySize_{0, 0};  // empty_'s default size
    SamplerHandle nearest_;
    VertexArrayHandle vertexArray_;
    int channelsLocation_ = -1;

    std::vector<Probe> probes_;
    std::vector<ActiveEffect> effects_;
    std::vector<int> effectOfPass_;  // schedule position → index into effects_, or -1
    std::vector<int> feederProbe_;   // schedule position → probe of a feeder, or -1
    std::vector<Feeder> feeders_;
    std::vector<Consumer> consumers_;
    bool consumerCondition_ = false;
    int slot_ = 0;                   // the query of this frame in each probe's ring
    int lastFrameSlot_ = -1;         // the last finished frame's, -1 before the first
    bool spanning_ = true;
    FramePlanOptions::ContentSkipDecision decision_ = FramePlanOptions::ContentSkipDecision::CpuWhenKnown;
    int conditionOf_ = -1;           // the probe whose condition is active, or -1
    int notIssued_ = 0, lastNotIssued_ = 0;
    std::map<std::string, std::string> skipped_;
    std::map<std::string, std::string> runningAlways_;
};

}  // namespace rmfx
