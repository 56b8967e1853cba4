#pragma once
// rmfx.Renderer: a workspace's run, kept between calls. It holds its own headless GL context and
// the executor (gl/GlExecutor.h) that the last run built, so that a render with the same inputs,
// target and check reuses the linked programs and allocated targets: new values go to the
// executor (setVariable), new images to its inputs (replaceInputImage), and the frames go on
// from where the last call stopped. A call that needs another plan (other inputs given, another
// target, check on or off, other effects selected, an input of another size) compiles the run
// anew from the workspace (compile/RunPreparation.h), as rmfx render does, and starts at time 0.

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "gl/GlContext.h"
#include "gl/GlExecutor.h"
#include "python/PyWorkspace.h"

namespace rmfx::python {

class PyRenderer {
public:
    // size: (0, 0) renders as rmfx render without --size (the first scene image's size, else the
    // workspace's). timing: per-pass GPU timers on (a little slower).
    PyRenderer(std::shared_ptr<PyWorkspace> ws, glm::ivec2 size, bool timing);
    ~PyRenderer();
    PyRenderer(const PyRenderer&) = delete;
    PyRenderer& operator=(const PyRenderer&) = delete;

    // Runs `frames` frames of dt seconds and reads `target` ("" the workspace's output) back.
    pybind11::array_t<float> render(const pybind11::dict& inputs, int frames, double dt, const std::string& target, bool check);
    std::string explain();
    void reset();  // the next render compiles anew and starts at time 0

    const std::vector<PassTiming>& timings() const { return timings_; }
    double frameMilliseconds() const { return frameMilliseconds_; }
    const std::vector<HealthFinding>& findings() const { return findings_; }
    const Diagnostics& warnings() const { return warnings_; }
    int frame() const { return executor_ ? executor_->frameIndex() : 0; }
    double time() const { return time_; }
    glm::ivec2 viewport() const { return executor_ ? executor_->viewport() : glm::ivec2(0); }
    std::vector<std::string> passesRun() const;

private:
    // What the executor was built for: a render that asks for the same reuses it.
    struct Plan {
        std::vector<std::pair<std::string, glm::ivec2>> inputs;  // given inputs and their images' sizes
        std::string target;
        bool check = false;
        std::uint64_t effectsRevision = 0;
        bool operator==(const Plan&) const = default;
    };
    struct Given {
        InputArgument argument;  // its `image` filled (arrays and files alike)
        const ImageInput* input = nullptr;
    };
    std::vector<Given> readInputs(const pybind11::dict& inputs) const;
    void build(const std::vector<Given>& given, const Plan& plan);
    void update(const std::vector<Given>& given);
    void makeCurrent();

    std::shared_ptr<PyWorkspace> ws_;
    glm::ivec2 size_{0};
    bool timing_ = false;
    std::unique_ptr<GlContext> context_;
    std::unique_ptr<GlExecutor> executor_;
    std::optional<Plan> plan_;
    std::uint64_t valuesRevision_ = 0;
    std::map<std::string, std::string> inputFiles_;  // for explain(): what each input was given
    double time_ = 0.0;
    std::vector<PassTiming> timings_;
    double frameMilliseconds_ = 0.0;
    std::vector<HealthFinding> findings_;
    Diagnostics warnings_;
};

// rmfx.Renderer, rmfx.PassTiming, rmfx.HealthFinding, and Workspace.renderer(…).
void bindRenderer(pybind11::module_& m);

}  // namespace rmfx::python
