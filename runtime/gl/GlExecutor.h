#pragma once
// Runs a workspace's frame plan (graph/FramePlan) as ordered OpenGL passes. Owns every GL object
// it creates: render targets (double-buffered where a pass reads them with frame="previous"),
// textures, meshes, programs and sampler objects. Shares ownership of the workspace it runs, so
// the caller may let its own copy go. Needs a current GL 4.5 context (GlContext), current also
// when it is destroyed.

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "compile/CompiledFrame.h"
#include "core/Result.h"
#include "gl/GlUniformUpload.h"
#include "graph/FramePlan.h"
#include "model/Image.h"
#include "model/OrbitCamera.h"
#include "model/PassTiming.h"
#include "model/TargetHealth.h"
#include "model/Workspace.h"

namespace rmfx {

// What only the GL run needs, apart from the compiled frame it runs.
struct GlRunSettings {
    ContentSkipDecision contentSkipDecision = ContentSkipDecision::CpuWhenKnown;
    HealthCheckMethod healthCheckMethod = HealthCheckMethod::Automatic;  // with the plan's checkHealth
};

// The plan's options and the GL run's settings in one: what the convenience create() and the
// runs built on it (run/HeadlessRun, sequences, replay) take.
struct ExecutorOptions : FramePlanOptions, GlRunSettings {
    using ContentSkipDecision = rmfx::ContentSkipDecision;
};

class GlExecutor {
public:
    // Runs a compiled frame (compile/CompiledFrame.h): links the programs of the passes it can run
    // (under any setting of the effect switches), loads their textures and meshes and allocates
    // the targets planned for its viewport. Errors name the pass, target or texture; warnings
    // (vertex streams the shaders do not read, …) come with the executor.
    static Result<std::unique_ptr<GlExecutor>> create(std::shared_ptr<const CompiledFrame> frame, const GlRunSettings& settings = {});
    // create() for a reload of the workspace file: the textures named in `reusableTextures` that
    // `previous` holds with the same declaration and files (or supplied image) are copied from it
    // on the GPU instead of being read and decoded again (the caller knows their files did not
    // change). `previous` is not modified.
    static Result<std::unique_ptr<GlExecutor>> createReusing(std::shared_ptr<const CompiledFrame> frame,
                                                             const GlRunSettings& settings, const GlExecutor& previous,
                                                             const std::vector<std::string>& reusableTextures);
    // Both in one: compiles the frame for `viewport` against this context's limits, then runs it.
    static Result<std::unique_ptr<GlExecutor>> create(std::shared_ptr<const Workspace> ws, glm::ivec2 viewport,
                                                      const ExecutorOptions& options = {});
    static Result<std::unique_ptr<GlExecutor>> createReusing(std::shared_ptr<const Workspace> ws, glm::ivec2 viewport,
                                                             const ExecutorOptions& options, const GlExecutor& previous,
                                                             const std::vector<std::string>& reusableTextures);
    ~GlExecutor();
    GlExecutor(const GlExecutor&) = delete;
    GlExecutor& operator=(const GlExecutor&) = delete;

    // Runs the scheduled passes once: the graph of the current effect switches. Errors (GL errors,
    // incomplete framebuffers) name the pass.
    Result<void> renderFrame(const FrameClock& clock);
    int frameIndex() const { return frame_; }  // frames rendered so far

    // Current value of a workspace variable; setVariable checks the type (a colour takes rgb or
    // rgba as declared). Targets whose format or size the variable picks are allocated anew, back
    // to their initial value. A switch variable of an effect culls or restores its passes from the
    // next frame on, with no recompile and no allocation. On any error nothing changes: the value,
    // the plan and the targets stay as they were.
    const Value* variable(const std::string& name) const;
    Result<void> setVariable(const std::string& name, const Value& value);

    // Per-pass GPU timing. Off by default: queries cost a little. Results arrive a frame or two
    // late (never stalling the pipeline); passTimings() holds the newest completed frame, in
    // schedule order, and is empty until one has completed.
    void setTimingEnabled(bool enabled);
    const std::vector<PassTiming>& passTimings() const;
    // First pass start to last pass end of the frame passTimings() last returned (it does not look
    // for a newer one, so the two always describe the same frame).
    double frameGpuMilliseconds() const;

    OrbitCamera& camera() { return camera_; }
    // The cursor for the MouseCoordinate… and …MouseButton semantics: pixels from the viewport's
    // top-left corner, and left/middle/right held (1) or not (0). Headless: 0.
    void setMouse(glm::vec2 pixels, glm::ivec3 buttons = glm::ivec3(0));
    glm::ivec2 viewport() const { return viewport_; }

    // Reads a render target (or "output") back as float RGBA, row 0 at the top. An error when the
    // frame did not compute it or another target has since reused its memory (not an output).
    Result<Image> readTarget(const std::string& name) const;
    std::vector<std::string> targetNames() const;
    glm::ivec2 targetSize(const std::string& name) const;
    TargetFormat targetFormat(const std::string& name) const;
    // The GL texture holding the newest finished contents of a target (0 if none): for display
    // (ImGui::Image) only; it stays owned by the executor and may change after setVariable.
    unsigned targetTexture(const std::string& name) const;

    const Workspace& workspace() const;
    // What the executor runs: the compiled frame, the frame plan (its targets are what is
    // allocated now), the graph of the current effect switches (its schedule is what the next
    // frame runs), the effects asked for and those switched off. None of these does GL work.
    const CompiledFrame& compiledFrame() const;
    const FramePlan& framePlan() const;
    const PassGraph& graph() const;
    const TargetPlan& targetPlan() const;
    const std::set<std::string>& askedEffects() const;
    const std::set<std::string>& switchedOffEffects() const;
    // The passes the last frame ran, in order.
    const std::vector<std::string>& passesRun() const;
    // The effects whose passes the last frame skipped on the GPU because their source held
    // nothing (<effect source>, docs/workspace-format.md), each with why. `wait`: for the GPU's
    // answer (after a headless frame); else what has arrived, as the editor asks each frame.
    const std::map<std::string, std::string>& contentSkippedEffects(bool wait = true);
    // The effects with a source that content skip runs whatever their source holds, each with why
    // (a target of theirs is an output: it must hold what their passes write).
    std::map<std::string, std::string> effectsRunningWhateverTheContent() const;
    // The passes content skip draws compiled without the effects they read, where those are
    // skipped (ContentSkipPlan's consumers whose code reads them), each with the effects, for the
    // current switches.
    std::map<std::string, std::set<std::string>> passesDrawnWithoutSkippedEffects() const;
    // The passes outside the effects drawn only where effects with a source run, since only they
    // read what those passes write (ContentSkipPlan's feeders), each with the effects.
    std::map<std::string, std::set<std::string>> passesDrawnOnlyForEffects() const;
    // How many passes of the last frame content skip left out on the CPU, the source's answer
    // having arrived before they were issued (the others it skipped, the GPU did).
    int passesNotIssuedByContentSkip() const;
    // With FramePlanOptions::checkHealth, what the last frame's passes left in their targets
    // (model/TargetHealth.h); null otherwise or before the first frame. The results come back from
    // the GPU after the frame: `wait` waits for the last frame's; without it, the latest frame
    // whose results are in (no stall; a frame or two behind).
    const FrameHealth* frameHealth(bool wait = true);
    // The first finding of each kind over every frame so far, in HealthKind order (waits for the
    // last frame's results).
    const std::vector<HealthFinding>& firstHealthFindings();

    // Hot reload (LiveWorkspace). Each is all or nothing: on any error the executor is left
    // exactly as it was, and the diagnostics say why.
    // Compiles and links the named passes' programs anew from their files; only when every one
    // succeeds are they swapped in (uniforms and samplers bound anew) and the old ones deleted.
    Result<void> recompilePasses(const std::vector<std::string>& passNames);
    // Reads a texture's image files again and replaces its GL texture.
    Result<void> reloadTexture(const std::string& name);
    // The next image of an <input> an image was given for at creation (FramePlanOptions::
    // givenInputs), such as the next frame of a sequence; it replaces the input's GL texture from
    // the next frame on. Unlike the creation's image it is not resampled: give it at the size the
    // first one had where the input sets the viewport.
    Result<void> replaceInputImage(const std::string& name, std::shared_ptr<const Image> image);
    // The next image of such an <input> written into its GL texture in place, straight from the
    // caller's memory (no copy, no new texture), where the texture takes the pixels as they are: a
    // 2D float RGBA texture of one level (linear colour, no mipmaps) of the same size. Returns
    // false, doing nothing, where it does not; replaceInputImage then takes them as an Image.
    struct InputPixels {
        const void* data = nullptr;  // rows top first, each `rowBytes` after the last
        int width = 0, height = 0;
        bool half = false;           // float16 RGBA; else float32 RGBA
        std::size_t rowBytes = 0;
    };
    bool writeInputPixels(const std::string& name, const InputPixels& pixels);
    // Reads a model file again (as a pass's <draw file="…"> names it) and replaces its mesh.
    Result<void> reloadModel(const std::string& file);
    // The GL program of an enabled pass (0 for none): a different one once the pass is recompiled.
    unsigned passProgram(const std::string& pass) const;
    // The GL texture object of a workspace texture (0 for none): a different one once reloaded.
    unsigned textureObject(const std::string& name) const;

private:
    struct Impl;  // gl/GlExecutorImpl.h
    struct Build;
    explicit GlExecutor(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
    OrbitCamera camera_;
    glm::ivec2 viewport_{0};
    int frame_ = 0;
};

}  // namespace rmfx
