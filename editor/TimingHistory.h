#pragma once
// Per-pass GPU times over recent frames: what the Timing panel's table (this frame, running
// average) and graph (frame totals) show. Fed once per editor frame with GlExecutor's newest
// completed timings; no GL, unit-tested.

#include <cstddef>
#include <deque>
#include <string>
#include <vector>

#include "model/PassTiming.h"

namespace rmfx::editor {

class TimingHistory {
public:
    explicit TimingHistory(std::size_t frames = 120) : capacity_(frames) {}

    // One frame's timings (schedule order) and its first-pass-start to last-pass-end total. An
    // empty list (no frame completed yet) is ignored. When the passes differ from the previous
    // frame's (a reload changed them) the history starts over.
    void add(const std::vector<PassTiming>& passes, double frameMilliseconds);
    void clear();

    struct Row {
        std::string pass;
        double lastMilliseconds = 0.0;
        double averageMilliseconds = 0.0;  // over the frames held
    };
    std::vector<Row> rows() const;
    double lastFrameMilliseconds() const;
    double averageFrameMilliseconds() const;
    // Frame totals, oldest first, as floats for ImGui::PlotLines; at most `frames` of them.
    std::vector<float> frameTotals() const;
    std::size_t size() const { return frames_.size(); }

private:
    struct Frame {
        std::vector<double> passes;
        double total = 0.0;
    };
    std::size_t capacity_;
    std::vector<std::string> names_;
    std::deque<Frame> frames_;
};

}  // namespace rmfx::editor
