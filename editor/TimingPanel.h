#pragma once
// The Timing section: per-pass GPU milliseconds (this frame and the average over the frames
// held), the frame total, and a graph of frame totals over the last ~120 frames. The passes of
// effects skipped by content are dimmed, with the time they took when they last ran: what the
// skip saves.

#include <map>
#include <set>
#include <string>

#include "editor/TimingHistory.h"
#include "gl/GlExecutor.h"

namespace rmfx::editor {

class TimingPanel {
public:
    // Once per rendered frame: takes the executor's newest completed timings.
    void record(GlExecutor& executor);
    void draw();
    void clear() {
        history_.clear();
        ranMilliseconds_.clear();
        skippedPasses_.clear();
    }

private:
    TimingHistory history_;
    std::map<std::string, double> ranMilliseconds_;  // a pass's GPU time the last frame it ran
    std::set<std::string> skippedPasses_;            // of the effects the content skipped
};

}  // namespace rmfx::editor
