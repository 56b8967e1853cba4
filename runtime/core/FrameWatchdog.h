#pragma once
// A shader that loops for minutes cannot be interrupted inside the GL driver, so headless runs
// (render, replay, CI) guard each frame with a time budget: when a frame has not finished in time,
// the watchdog reports what was running and ends the process with kExitFrameBudget instead of
// letting the job hang until an outer timeout kills it without a word.
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace rmfx {

// The exit status of a run stopped by its frame budget.
constexpr int kExitFrameBudget = 3;
// The budget of `rmfx render` and `rmfx replay` unless --frame-budget says otherwise.
constexpr double kDefaultFrameBudgetSeconds = 60.0;

class FrameWatchdog {
public:
    // `onTimeout` gets the message; it should not return (the default prints it to stderr and calls
    // std::_Exit(kExitFrameBudget)). If it does return, the watchdog stays quiet until re-armed.
    explicit FrameWatchdog(double budgetSeconds, std::function<void(const std::string&)> onTimeout = {});
    ~FrameWatchdog();
    FrameWatchdog(const FrameWatchdog&) = delete;
    FrameWatchdog& operator=(const FrameWatchdog&) = delete;

    // Starts the clock for work described by `what` (e.g. "frame 3 of shader_5.xml").
    void arm(std::string what);
    // The work finished in time.
    void disarm();

private:
    void watch();

    std::chrono::duration<double> budget_;
    std::function<void(const std::string&)> onTimeout_;
    std::mutex mutex_;
    std::condition_variable changed_;
    bool armed_ = false, stopping_ = false;
    std::chrono::steady_clock::time_point deadline_;
    std::string what_;
    std::thread thread_;
};

}  // namespace rmfx
