#pragma once
// The executor's state (gl/GlExecutor.h), private to the gl layer: what create(), renderFrame(),
// the reports and hot reload share. GlExecutor.cpp creates and runs frames, GlExecutorPasses.cpp
// makes the passes ready to draw, GlExecutorReports.cpp answers what the last frame did,
// GlExecutorReload.cpp swaps in what hot reload read anew.

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "compile/CompiledFrame.h"
#include "gl/GlContentSkip.h"
#include "gl/GlExecutor.h"
#include "gl/GlHealthCheck.h"
#include "gl/GlHealthObserver.h"
#include "gl/PassObserver.h"
#include "gl/GlMeshCache.h"
#include "gl/GlPassTimers.h"
#include "gl/GlProgramBuild.h"
#include "gl/GlRenderState.h"
#include "gl/GlRenderTargets.h"
#include "gl/GlTextureCache.h"
#include "gl/GpuPass.h"

namespace rmfx {

struct GlExecutor::Impl {
    std::shared_ptr<const CompiledFrame> compiled;
    const Workspace& ws;
    // The compiled frame's plan; its targets are planned again when a variable picks another
    // format or size.
    FramePlan plan;
    int maxTargetSize = 0;                // the context's: no target side beyond it
    std::map<std::string, Value> values;  // uniform slots point into it: nodes never move
    bool compatibility = false;           // the workspace's profile, checked against the context in create()
    GlRenderTargets targets;
    GlTextureCache textures;
    GlMeshCache meshes;
    std::vector<std::unique_ptr<GpuPass>> passes;  // linked: every pass some combination of switches runs
    std::set<int> readAnew;  // passes hot reload compiled from their files again: not the compiled frame's sources

    // The switches' combination (chosen when a value changes, no GL work) and its schedule; the
    // GL side follows it (content skip's queries, the second programs) at the next frame.
    FrameVariant current;
    std::vector<GpuPass*> schedule;
    bool variantReady = false;
    std::vector<std::string> lastFramePasses;
    GlPassTimers timers;
    GlRenderState renderState;  // what the frame's passes set so far
    std::unique_ptr<GlContentSkip> contentSkip;  // null without an effect with a source, or when off
    // Content skip's consumers compiled without the effects they read (ContentSkipPlan::Consumer),
    // by pass index with the effects left out; and for each schedule position, the one it draws.
    std::map<int, std::pair<std::set<std::string>, std::unique_ptr<GpuPass>>> withoutEffects;
    std::vector<const GpuPass*> withoutEffectsAt;
    std::unique_ptr<GlHealthCheck> healthCheck;  // with FramePlanOptions::checkHealth
    std::unique_ptr<GlHealthObserver> healthObserver;
    // What watches the passes (gl/PassObserver.h): the health check, then content skip.
    std::vector<PassObserver*> observers;
    std::optional<FrameHealth> lastHealth;
    std::vector<HealthFinding> firstFindings;  // of each kind, since the first frame
    glm::dvec2 mouse{0.0};
    glm::ivec3 mouseButtons{0};

    explicit Impl(std::shared_ptr<const CompiledFrame> frame)
        : compiled(std::move(frame)), ws(compiled->ws()), plan(compiled->plan), values(compiled->values) {}

    // The health of the frames whose results are in (all that ended, when `wait`), in order.
    void takeHealth(bool wait);
    GpuPass* compiledPass(int index) const;
    GpuPass* findPass(const std::string& name) const;
    // Points every sampler of the texture at its GL object (after it was loaded anew).
    void bindTexture(const std::string& name);

    // The combination the switch variables' values select and its schedule: a lookup.
    void chooseVariant();
    // Before a frame: content skip and the second programs follow the chosen combination.
    void prepareVariant();
    // How content skip draws the schedule: whether one condition may span an effect's passes, and
    // which passes it draws a second way (ContentSkipPlan::Consumer).
    void planSkippedDraws();
    // The pass at schedule `position` linked without `effects`, when that changes its code; null
    // otherwise, or when it does not build (it is then drawn as compiled, reading the cleared targets).
    const GpuPass* passWithout(size_t position, const GpuPass& gp, const std::set<std::string>& effects);

    // A pass ready to draw from its assembled `source`, or null with the diagnostics saying why.
    std::unique_ptr<GpuPass> buildPass(int index, const Result<PassProgramSource>& source, bool targetsAllocated, Diagnostics& d);
    // Gives the pass its program, with --check made to count what the pass writes where it can.
    bool useProgram(GpuPass& gp, PassGlProgram built, Diagnostics& d);
    // Whether the pass before or after `gp`, of those that may run, writes the target `gp` writes
    // (a scene drawn model by model; culling by the effect switches aside).
    bool sharesItsTargetWithANeighbour(const GpuPass& gp) const;
    // The pass's program made to count what it writes, recording the samplers `inputs`
    // (gl/HealthInstrumentation.h); where it cannot, it stays as built and the check inspects its
    // target after it ran.
    void countOwnWrites(GpuPass& gp, const PassGlProgram& built, std::vector<std::string> inputs);
    // What `gp` draws, with another program, bound; null when binding fails (what binding the
    // pass's own program said is not said again).
    std::unique_ptr<GpuPass> withProgram(const GpuPass& gp, ProgramHandle program, std::set<std::string> initialized);
    // What the health check calls a 2D input of a pass (targets and 2D textures); none for others.
    std::optional<std::string> healthInputLabel(const SamplerSlot& slot) const;
    bool bindProgram(GpuPass& gp, Diagnostics& d);
};

}  // namespace rmfx
