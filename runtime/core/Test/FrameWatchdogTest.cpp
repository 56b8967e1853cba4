// The watchdog calls its handler once a frame outlives the budget, and never for a frame that
// finished in time.
#include "core/FrameWatchdog.h"

#include <atomic>
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

namespace rmfx {
namespace {

using namespace std::chrono_literals;

struct Recorder {
    std::mutex mutex;
    std::vector<std::string> messages;
    std::function<void(const std::string&)> handler() {
        return [this](const std::string& m) {
            std::lock_guard lock(mutex);
            messages.push_back(m);
        };
    }
    size_t count() {
        std::lock_guard lock(mutex);
        return messages.size();
    }
};

TEST(FrameWatchdog, AFramePastTheBudgetIsReportedOnce) {
    Recorder recorder;
    FrameWatchdog watchdog(0.05, recorder.handler());
    watchdog.arm("frame 7 of spin.xml");
    auto until = std::chrono::steady_clock::now() + 10s;
    while (recorder.count() == 0 && std::chrono::steady_clock::now() < until) std::this_thread::sleep_for(5ms);
    std::this_thread::sleep_for(200ms);  // no second report for the same frame
    ASSERT_EQ(recorder.count(), 1u);
    EXPECT_EQ(recorder.messages[0],
              "frame 7 of spin.xml did not finish within the frame budget of 0.05 s (a shader may loop for too long; "
              "raise the budget with --frame-budget SECONDS)");
}

TEST(FrameWatchdog, FramesThatFinishInTimeAreNotReported) {
    Recorder recorder;
    {
        FrameWatchdog watchdog(0.3, recorder.handler());
        for (int i = 0; i < 20; ++i) {
            watchdog.arm("frame");
            std::this_thread::sleep_for(10ms);
            watchdog.disarm();
        }
        std::this_thread::sleep_for(500ms);  // past the budget of the last frame, disarmed
    }
    EXPECT_EQ(recorder.count(), 0u);
}

}  // namespace
}  // namespace rmfx
