#pragma once
// The Timing section: per-pass GPU milliseconds (this frame and the average over the frames
// held), the frame total, and a graph of frame totals over the last ~120 frames.

#include "editor/TimingHistory.h"
#include "gl/GlExecutor.h"

namespace rmfx::editor {

class TimingPanel {
public:
    // Once per rendered frame: takes the executor's newest completed timings.
    void record(const GlExecutor& executor);
    void draw();
    void clear() { history_.clear(); }

private:
    TimingHistory history_;
};

}  // namespace rmfx::editor
