#pragma once
// Which passes a frame runs, as a dependency graph in the manner of Filament's frame graph. A
// pass reads targets through its samplers (this frame's contents: the last earlier pass that wrote
// them; frame="previous": what the last frame left) and its own target when it blends or draws a
// mesh without clearing; it writes its target. From the outputs asked for, only the passes they
// transitively need run, in document order. Pure: no GL.

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/Diagnostic.h"
#include "core/Result.h"
#include "model/Workspace.h"

namespace rmfx {

enum class PassFate {
    Run,
    Disabled,           // enabled="false"
    EffectLeftOut,      // its effect was not asked for
    EffectSwitchedOff,  // its effect's switch variables are all off
    InputGiven,         // it draws a target an image given for an <input> replaces
    InputNotGiven,      // it samples an <input> no image was given for (the workspace draws the target)
    NotNeeded,          // nothing asked for reads what it writes
};

struct PassNode {
    const Pass* pass = nullptr;
    std::string target;             // the target it writes, resolved
    const Effect* effect = nullptr; // the effect it belongs to, if any
    bool loadsTarget = false;       // blends, or draws a mesh without clearing: keeps what the target held
    bool active = false;            // enabled, and its effect (if any) asked for and switched on
    PassFate fate = PassFate::NotNeeded;
    std::string why;                // why it runs or is culled, for --explain
    std::vector<int> inputs;        // earlier passes whose results it reads this frame
    std::vector<int> carried;       // passes whose results of the last frame it reads
    std::vector<std::string> skippedInputs;  // targets of effects that are off, which its shaders skip
    // Its effect's <effect gate>, which content skip counts before the effect's first pass (the
    // pass that writes it is an input); empty when there is none or content skip is off.
    std::string gate;
};

// Why an <input> culls a pass: an image was given for an input that replaces the target the pass
// draws, and the pass comes before the first pass sampling the input (InputGiven); or the pass
// samples an input that replaces a target and no image was given (InputNotGiven).
struct InputCulling {
    PassFate fate;
    std::string why;
};
std::optional<InputCulling> cullingByInputs(const Workspace& ws, const std::set<std::string>& givenInputs, int passIndex);

struct FrameRequest {
    std::vector<std::string> outputs;     // targets read after the frame; empty: the workspace's output
    std::set<std::string> effects;        // effects asked for
    std::set<std::string> switchedOff;    // asked for, but switched off this frame
    std::set<std::string> givenInputs;    // <input>s an image was given for (rmfx render --input)
    bool contentSkip = false;             // effects with a gate read it (FramePlanOptions::contentSkip)
};

struct PassGraph {
    std::vector<PassNode> nodes;          // one per pass, in document order
    std::vector<int> schedule;            // the passes that run, in document order
    std::vector<std::string> outputs;     // the outputs asked for, resolved
    // Targets whose contents carry over from frame to frame: read with frame="previous", or loaded
    // by a pass before any pass of the frame writes them.
    std::set<std::string> carriedTargets;

    int passIndex(const std::string& name) const;  // -1 when there is no such pass
};

// Errors name the pass and the target: an output nothing writes, a pass reading a target that no
// running pass wrote earlier in the frame.
Result<PassGraph> buildPassGraph(const Workspace& ws, const FrameRequest& request);

// The order problems validation reports, with every pass enabled and every effect on: a cycle of
// passes reading each other's targets, and a pass reading a target nothing wrote earlier in the
// frame (and not asked for from the last frame with frame="previous"). Each names the passes.
Diagnostics checkPassOrder(const Workspace& ws);

const char* passFateName(PassFate fate);  // "run", "culled: disabled", …

}  // namespace rmfx
