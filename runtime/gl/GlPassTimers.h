#pragma once
// Per-pass GPU timing with timestamp queries, three frames in flight: results are read a frame or
// two late, never stalling the pipeline unless the slot about to be reused is still pending.
// Needs a current GL context.

#include <string>
#include <vector>

#include "gl/GlHandles.h"
#include "model/PassTiming.h"

namespace rmfx {

class GlPassTimers {
public:
    void setEnabled(bool enabled);
    bool enabled() const { return enabled_; }

    // When enabled: stamps the start of a frame of `passCount` passes; passDone() after each.
    void beginFrame(size_t passCount);
    void passDone(const std::string& pass);

    // The newest completed frame (reads what has arrived), in schedule order.
    const std::vector<PassTiming>& timings();
    double frameMilliseconds() const { return frameMilliseconds_; }

private:
    // Timestamps of one frame's passes: queries[0] before the first pass, queries[i + 1] after pass i.
    struct Frame {
        std::vector<QueryHandle> queries;
        std::vector<std::string> passes;
        bool pending = false;
    };
    void collect(bool waitForNext);

    bool enabled_ = false;
    Frame frames_[3];
    int next_ = 0;
    Frame* current_ = nullptr;
    std::vector<PassTiming> timings_;
    double frameMilliseconds_ = 0.0;
};

}  // namespace rmfx
