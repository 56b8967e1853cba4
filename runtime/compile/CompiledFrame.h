#pragma once
// Compile, then execute: the finished plan of a run, made before any GL object exists. It holds
// the frame plan (the effects asked for, the pass graph and content skip's plan of every
// combination of their switches, the targets at the run's size and declared values), each pass's
// program source assembled once with the effects' prelude, and for each consumer content skip
// may draw compiled without the effects it reads, that second program's source, where leaving
// the effects out changes the code (glslang's preprocessor decides, not a search for names).
// Immutable once made: the GL executor runs one (gl/GlExecutor.h), and `rmfx render --explain`
// prints one without a GL context.

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include <glm/vec2.hpp>

#include "core/Result.h"
#include "frontend/shader/PassProgram.h"
#include "graph/FrameExplanation.h"
#include "graph/FramePlan.h"
#include "validation/Validation.h"
#include "model/Workspace.h"

namespace rmfx {

// A consumer's second program (ContentSkipPlan::Consumer): its source with `effects` left out.
struct ProgramWithoutEffects {
    std::set<std::string> effects;
    PassProgramSource source;
};

struct CompiledFrame {
    std::shared_ptr<const Workspace> workspace;
    glm::ivec2 viewport{0};
    int maxTargetSize = 0;                 // the limit the targets were planned against
    std::map<std::string, Value> values;   // each variable's declared value: what the first frame uses
    FramePlan plan;                        // its targets planned for `values` at `viewport`
    // Every pass some combination of switches runs, by index into Workspace::passes: its stages
    // assembled with plan.prelude, or why they are not (missing file, include error, …).
    std::map<int, Result<PassProgramSource>> programs;
    // By combination of switched-off effects, then schedule position: the consumers whose second
    // program differs from the first. Empty with --check (the check looks at every pass as compiled).
    std::map<std::set<std::string>, std::map<size_t, ProgramWithoutEffects>> withoutEffects;

    const Workspace& ws() const { return *workspace; }
    // The second program of scheduled pass `position` under `switchedOff`, or null.
    const ProgramWithoutEffects* programWithout(const std::set<std::string>& switchedOff, size_t position) const;
    // The passes drawn compiled without the effects they read, by name, under `switchedOff`.
    std::map<std::string, std::set<std::string>> passesDrawnWithoutSkippedEffects(const std::set<std::string>& switchedOff) const;
    // The feeders content skip draws only where their effects run, by name, under `switchedOff`.
    std::map<std::string, std::set<std::string>> passesDrawnOnlyForEffects(const std::set<std::string>& switchedOff) const;
    // The effects with a source content skip runs whatever it holds, with why, under `switchedOff`.
    std::map<std::string, std::string> effectsRunningWhateverTheContent(const std::set<std::string>& switchedOff) const;
};

// The largest target side a GL 4.5 context must support (GL_MAX_TEXTURE_SIZE's minimum); the
// limit a plan made without a context is checked against.
constexpr int kGuaranteedMaxTargetSize = 16384;

// Plans the frame for `options` at `viewport` (checked against `maxTargetSize` and the memory
// budget first), assembles every runnable pass's program and content skip's second programs.
// Errors: an empty or oversized viewport, effects not declared, passes reading what nothing wrote,
// a format or scale no value picks, targets over the limits. A pass whose shaders do not assemble
// is no error here: its program holds why, for whoever builds it. `checked`: the programs
// validation assembled and compiled (validation/Validation.h), taken as they are where they were
// assembled with the plan's prelude, so that a run reads and assembles each shader once.
Result<std::shared_ptr<const CompiledFrame>> compileFrame(std::shared_ptr<const Workspace> ws, const FramePlanOptions& options,
                                                          glm::ivec2 viewport, int maxTargetSize = kGuaranteedMaxTargetSize,
                                                          const CheckedPrograms* checked = nullptr);

// The source of `pass` compiled with `effects` left out of the plan's asked effects, when leaving
// them out changes its code (`asCompiled`: its source with the plan's prelude); nullopt when it
// does not, or when it does not assemble. Hot reload asks again for a pass read anew.
std::optional<PassProgramSource> programWithoutEffects(const Workspace& ws, const Pass& pass, const FramePlan& plan,
                                                       const PassProgramSource& asCompiled, const std::set<std::string>& effects);

// What `--explain` prints of the frame under `switchedOff`: everything but the files given for the
// inputs and what a rendered frame's content skip left out (FrameExplanationInput::contentSkipped).
FrameExplanationInput explanationOf(const CompiledFrame& frame, const std::set<std::string>& switchedOff);

}  // namespace rmfx
