#include "core/FrameWatchdog.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace rmfx {

namespace {

std::string secondsText(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", seconds);
    return text;
}

}  // namespace

FrameWatchdog::FrameWatchdog(double budgetSeconds, std::function<void(const std::string&)> onTimeout)
    // At most about 31 years, so that the deadline stays within the clock's range.
    : budget_(std::min(budgetSeconds, 1e9)), onTimeout_(std::move(onTimeout)) {
    if (!onTimeout_)
        onTimeout_ = [](const std::string& message) {
            std::fprintf(stderr, "rmfx: error: %s\n", message.c_str());
            std::fflush(stderr);
            std::fflush(stdout);
            std::_Exit(kExitFrameBudget);
        };
    thread_ = std::thread([this] { watch(); });
}

FrameWatchdog::~FrameWatchdog() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    changed_.notify_all();
    thread_.join();
}

void FrameWatchdog::arm(std::string what) {
    {
        std::lock_guard lock(mutex_);
        armed_ = true;
        what_ = std::move(what);
        deadline_ = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(budget_);
    }
    changed_.notify_all();
}

void FrameWatchdog::disarm() {
    {
        std::lock_guard lock(mutex_);
        armed_ = false;
    }
    changed_.notify_all();
}

void FrameWatchdog::watch() {
    std::unique_lock lock(mutex_);
    while (!stopping_) {
        if (!armed_) {
            changed_.wait(lock);
            continue;
        }
        if (changed_.wait_until(lock, deadline_) == std::cv_status::no_timeout) continue;
        if (!armed_ || stopping_ || std::chrono::steady_clock::now() < deadline_) continue;
        armed_ = false;
        std::string message = what_ + " did not finish within the frame budget of " + secondsText(budget_.count()) +
                              " s (a shader may loop for too long; raise the budget with --frame-budget SECONDS)";
        lock.unlock();
        onTimeout_(message);
        lock.lock();
    }
}

}  // namespace rmfx
