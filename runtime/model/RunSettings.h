#pragma once
// How long and how large a headless run is: what `rmfx render` takes from its options and a replay
// case from its manifest (run/HeadlessRun runs it).

#include <functional>
#include <string>

#include <glm/vec2.hpp>

namespace rmfx {

struct RunSettings {
    RunSettings(glm::ivec2 size = glm::ivec2(0), int frames = 1, float deltaTime = 1.0f / 60.0f)
        : size(size), frames(frames), deltaTime(deltaTime) {}

    glm::ivec2 size;  // 0: the workspace's size
    int frames;
    float deltaTime;
    // Seconds a frame may take, GPU work included, before the run is stopped (FrameWatchdog:
    // the process exits with kExitFrameBudget); 0: no limit.
    double frameBudgetSeconds = 0.0;
    // What happens then (default: the message on stderr, exit); gets the message, should not return.
    std::function<void(const std::string&)> onFrameBudget;
};

}  // namespace rmfx
