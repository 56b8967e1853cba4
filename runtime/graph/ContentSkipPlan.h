#pragma once
// What content skip (<effect source>, gl/GlContentSkip.h) does with one schedule, decided before
// any GL object exists: which effects with a source it may skip, the probe each is decided by (the
// source, or the gate counted in its place), where each effect starts and ends, the targets it
// hands on (cleared to zero where it is skipped), the feeders (passes outside the effects that
// only they read, drawn under the same condition) and the consumers (passes after the effects that
// read what they hand on, which may be drawn compiled without them). Pure: no GL. The executor
// gives the plan of the current switches to GlContentSkip; `--explain` prints it.

#include <map>
#include <set>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "model/Workspace.h"

namespace rmfx {

struct ContentSkipPlan {
    // One occlusion query a frame: the target counted and its channels. Effects on the same
    // source and channels share one.
    struct Probe {
        std::string source;
        glm::bvec4 channels{false};
    };
    // A target the effect writes that something after it reads: cleared to zero where the effect
    // is skipped (unless nothing would read the zeros: the executor decides that from what the
    // consumers' second programs sample).
    struct HandedOn {
        std::string target;
        bool readBack = false;        // after the frame (the editor reads every target)
        std::vector<size_t> readers;  // schedule positions of the passes outside the effect that sample it
    };
    struct SkippableEffect {
        const Effect* effect = nullptr;
        size_t probe = 0;             // into probes
        bool gated = false;           // the probe counts its gate, not its source
        size_t first = 0, last = 0;   // schedule positions of its first and last pass
        std::vector<HandedOn> handedOn;
    };
    // A pass outside the effects whose target only passes drawn under one probe's condition read
    // (effect passes, or other feeders), written after the source is complete and read back by
    // nothing after the frame: it is drawn under that condition too.
    struct Feeder {
        size_t position = 0;            // in the schedule
        std::set<std::string> effects;  // the effects that read it, directly or through other feeders
        size_t probe = 0;
    };
    // A pass outside the effects that reads what effects sharing one probe hand on (hdr_lighting's
    // final, after bloom and star): where the probe finds nothing it can be drawn compiled with
    // those effects left out (their RMFX_EFFECT_* false), and as compiled where it finds something.
    struct Consumer {
        size_t position = 0;            // in the schedule
        std::set<std::string> effects;  // left out of the second program
        size_t probe = 0;               // the one their sources share
    };

    std::vector<Probe> probes;
    std::vector<SkippableEffect> effects;
    std::vector<Feeder> feeders;      // in schedule order
    std::vector<Consumer> consumers;  // in schedule order
    // The effects with a source that content skip leaves running whatever it holds, each with why
    // (a target it writes is read back after the frame, and must hold what its passes write, not
    // zeros: running a pass on a zero source can still write a non-zero alpha).
    std::map<std::string, std::string> runningAlways;

    bool empty() const { return effects.empty(); }
    // The probe whose condition scheduled pass `position` is drawn under (an effect's pass or a
    // feeder), or -1.
    int probeAt(size_t position) const;
    bool endsAnEffect(size_t position) const;

    std::vector<int> effectOfPass;  // schedule position → index into effects, or -1
    std::vector<int> feederProbe;   // schedule position → probe of a feeder, or -1
};

// The plan for `schedule` (indices into Workspace::passes, in order); `outputs`: the targets read
// after the frame (empty: every target). Effects whose source is not a target, or with no pass in
// the schedule, are left out.
ContentSkipPlan planContentSkip(const Workspace& ws, const std::vector<int>& schedule, const std::vector<std::string>& outputs);

// Whether any effect declares a source: content skip has something to do.
bool hasSourcedEffects(const Workspace& ws);

}  // namespace rmfx
