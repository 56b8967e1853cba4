#pragma once
// The numeric health check of rmfx render --check (model/TargetHealth.h), done on the GPU. A pass
// whose fragment shader was made to count what it writes (HealthInstrumentation.h) counts during
// its own draw (beforeCountingPass). After any other pass, draws over the target's size (into a
// framebuffer without attachments) read the target it wrote: a screen lets through, in an
// occlusion query, only texels outside what the format holds without a finding; where it let one
// through (conditional rendering), a count draw counts the pixels holding each kind (NaN, ±Inf,
// negative, at the format's largest) with atomics in a storage buffer and keeps the first such
// pixel in reading order, and a draw of five fragments records, for each kind the pass holds,
// that pixel's value and its inputs' texels there. The inspections wait until a pass is about to
// write memory one of them reads, or the frame ends, and then run together: the draws of one kind
// do not wait for each other, and one barrier orders the counts before the records (a barrier and
// a wait after every pass cost an NVIDIA H200 about 29 µs each). Nothing is read back during the
// frame, and nothing when it ends: each frame counts into a buffer of its own, and
// its counts (a few hundred bytes per pass) and the records of each kind's first pass are read
// once a fence after its last draw has signalled, or when asked for with `wait`. Reading them at
// the end of each frame made an H200 wait for the whole frame: 16 % of a 512x512 frame. The
// records are read only for a frame with a finding.
// Needs a current GL 4.5 context.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/Result.h"
#include "gl/GlHandles.h"
#include "gl/HealthInstrumentation.h"
#include "model/TargetHealth.h"

namespace rmfx {

class GlHealthCheck {
public:
    // Automatic resolves from the context's renderer (model/TargetHealth.h).
    static Result<std::unique_ptr<GlHealthCheck>> create(HealthCheckMethod method);
    // Whether a pass's program should be made to count what it writes. `sharesItsTarget`: the pass
    // before or after it writes the same target (hdr_lighting's scene, model by model), where each
    // inspection after a pass reads the whole target while counting runs only on the model's own
    // fragments. `inputs`: the 2D inputs its counting version would record. Automatic counts in
    // every pass on a GPU; on a software rasteriser, which runs the counting code of every
    // fragment, found or not, in passes that share their target or record at most
    // kSoftwareCountingInputs inputs (each recorded input is a fetch and a store of every fragment).
    bool countsWhileDrawing(bool sharesItsTarget, int inputs) const;
    static constexpr int kSoftwareCountingInputs = 2;

    // A 2D texture a pass sampled: what the report calls it, its GL object and the texture unit the
    // pass bound it to.
    struct Input {
        std::string sampler;  // the uniform
        std::string label;
        unsigned texture = 0;
        int unit = 0;
    };

    void beginFrame(int frame, size_t passes);
    // After scheduled pass `position` drew into `texture` (level 0 of `size`, of `format`,
    // `target`'s memory), reading its 2D `inputs`: the inspection waits until that memory is
    // about to be written again (beforeWriting) or the frame ends.
    // `whyNotWhileDrawing`: why the pass did not count what it wrote, where that was asked for.
    void afterPass(size_t position, const std::string& pass, const std::string& target, unsigned texture,
                   glm::ivec2 size, TargetFormat format, const std::vector<Input>& inputs,
                   const std::string& whyNotWhileDrawing = "", unsigned condition = 0);
    // Before pass `position`, whose program counts what it writes (`uniforms`, its program current),
    // draws into a target of `size` and `format`, reading `inputs` in the order its shader records.
    // `keepsEarlierPixels`: it leaves what the target held where it does not draw (PassHealth::ownPixelsOnly).
    void beforeCountingPass(size_t position, const std::string& pass, const std::string& target, glm::ivec2 size,
                            TargetFormat format, const std::vector<Input>& inputs, const HealthUniforms& uniforms,
                            bool keepsEarlierPixels);
    // The binding point of the check's buffer in the shaders that write it.
    int bufferBinding() const { return binding_; }
    // Before a pass writes `texture`: inspects, together, what waits on it.
    void beforeWriting(unsigned texture);
    // Inspects what still waits; the frame's results are read later (finishedFrames).
    void endFrame();
    // The frames ended since the last call whose results the GPU has written, oldest first: every
    // one of them when `wait` (which waits for their GPU work), else those whose fence has signalled.
    std::vector<FrameHealth> finishedFrames(bool wait);

private:
    struct Inspection {
        size_t position = 0;
        unsigned texture = 0;
        glm::ivec2 size{0};
        FormatHealthLimits limits;
        std::vector<Input> inputs;
        // The query deciding whether the pass was drawn (content skip, gl/GlContentSkip.h): the
        // inspection is drawn under it, so that a pass left out is not judged by what its target
        // held before. 0: drawn.
        unsigned condition = 0;
    };

    // A frame's results on their way back: the buffer its passes count into (HealthBuffer.h), a
    // fence after its last draw, and what the report says of its passes.
    struct FrameInFlight {
        BufferHandle buffer;
        size_t capacity = 0;  // passes the buffer holds
        // The counts, copied after the frame into memory the CPU reads as it is (persistently
        // mapped): NVIDIA reads a GPU buffer back by a copy queued behind everything issued since,
        // so reading the last frame's during the next waited for that one too. Null: unmapped.
        BufferHandle counts;
        const std::int32_t* mapped = nullptr;
        FenceHandle fence;
        bool inFlight = false;  // ended, not read yet
        int frame = 0;
        std::vector<PassHealth> passes;
        std::vector<std::vector<std::string>> inputLabels;
        std::vector<glm::ivec2> sizes;  // of each pass's target
    };

    GlHealthCheck() = default;
    FrameInFlight& now() { return *now_; }
    void growBuffer(FrameInFlight& f, size_t passes);
    FrameHealth read(FrameInFlight& f);  // waits for its GPU work
    // What the report says of the pass; false when its target is not inspected.
    bool notePass(size_t position, const std::string& pass, const std::string& target, glm::ivec2 size, TargetFormat format,
                  const std::vector<Input>& inputs);
    void bindCommonState();
    void inspectPending();
    void overTarget(const Inspection& inspection);  // the framebuffer, viewport and target's unit
    void drawScreen(const Inspection& inspection);
    void drawCount(const Inspection& inspection);
    void drawPixel(const Inspection& inspection);  // binds the inputs to units 0…

    ProgramHandle screen_, reduce_, fetch_;
    int screenLowest_ = -1, screenHighest_ = -1;
    std::vector<QueryHandle> screens_;  // one per inspection of a batch: whether its screen found anything
    int reducePosition_ = -1, reduceChannels_ = -1, reduceNegatives_ = -1, reduceLargest_ = -1;
    int fetchPosition_ = -1, fetchInputCount_ = -1, fetchInputs_ = -1, fetchRecords_ = -1;
    int binding_ = 0;
    HealthCheckMethod method_ = HealthCheckMethod::WhileDrawing;
    bool software_ = false;  // llvmpipe, softpipe, SwiftShader
    FramebufferHandle empty_;     // no attachment: the shaders only write the buffers
    glm::ivec2 maxSize_{0, 0};    // the largest framebuffer
    glm::ivec2 emptySize_{0, 0};  // empty_'s default size
    VertexArrayHandle vertexArray_;
    // As many as frames are in flight (a frame's results are usually in before the next but one
    // begins): a frame takes one whose results were read, or a new one.
    std::vector<std::unique_ptr<FrameInFlight>> frames_;
    FrameInFlight* now_ = nullptr;
    std::vector<FrameInFlight*> inFlight_;  // oldest first
    std::vector<Inspection> pending_;
};

}  // namespace rmfx
