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
#include "run/FrameStepper.h"
#include "python/PyWorkspace.h"

namespace rmfx::python {

class PyRenderer {
public:
    // size: (0, 0) renders as rmfx render without --size (the first scene image's size, else the
    // workspace's). timing: per-pass GPU timers on (a little slower). frameBudget: seconds a frame
    // may take, as rmfx render --frame-budget (past it the process ends with status 3); 0: none.
    PyRenderer(std::shared_ptr<PyWorkspace> ws, glm::ivec2 size, bool timing, double frameBudget = 0.0);

    // rmfx render --memory-budget (MiB), --content-skip on|off and --no-pool for the runs this
    // renderer compiles from now on.
    void setRunOptions(std::optional<double> memoryBudgetMiB, bool contentSkip, bool poolTargets);
    ~PyRenderer();
    PyRenderer(const PyRenderer&) = delete;
    PyRenderer& operator=(const PyRenderer&) = delete;

    // Runs `frames` frames of dt seconds and reads `target` ("" the workspace's output) back.
    // dtype "float32", or "target": the target's own storage type (targetArray).
    pybind11::array render(const pybind11::dict& inputs, int frames, double dt, const std::string& target, bool check,
                           const std::string& dtype = "float32");
    // bench/python-overhead.py's reference: `frames` frames of this renderer's executor in a C++
    // loop, each giving the inputs' images (converted once, before the loop) as render() gives them,
    // rendering and reading the target back; the seconds of each frame. The run must have rendered.
    std::vector<double> cppFrameLoop(const pybind11::dict& inputs, int frames);
    std::string explain();
    void reset();  // the next render compiles anew and starts at time 0

    // A sequence (python/PySequence.h), as rmfx render runs one: a fresh run built for these
    // inputs and target, whose frame `first` of the shot comes at time first·dt, after `preroll`
    // frames of these images at the times before it (io/media/SequenceChunk.h).
    void beginSequence(const pybind11::dict& inputs, const std::string& target, double dt, int first, int preroll);
    // The sequence's next frame with these images; the target read back when `read`, else None.
    pybind11::object stepSequence(const pybind11::dict& inputs, bool read, const std::string& dtype = "float32");

    const PyWorkspace& workspace() const { return *ws_; }
    const std::vector<PassTiming>& timings() const { return timings_; }
    double frameMilliseconds() const { return frameMilliseconds_; }
    const std::vector<HealthFinding>& findings() const { return findings_; }
    const Diagnostics& warnings() const { return warnings_; }
    int frame() const { return executor_ ? executor_->frameIndex() : 0; }
    double time() const { return steps_ ? steps_->time(nextFrame_ - stepsBase_) : 0.0; }
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
        InputArgument argument;  // its `image` filled, except for an array the GPU can take as it is
        const ImageInput* input = nullptr;
        glm::ivec2 size{0};
        pybind11::object array;  // that array, and its pixels where it is one
        std::optional<GlExecutor::InputPixels> direct;
    };
    std::vector<Given> readInputs(const pybind11::dict& inputs) const;
    static const std::shared_ptr<const Image>& imageOf(Given& given);  // converting a direct array
    Plan planFor(const std::vector<Given>& given, const std::string& target, bool check) const;
    void build(std::vector<Given>& given, const Plan& plan);
    void update(std::vector<Given>& given);
    // Frames continue at step dt: a new step continues time from where the last one left it.
    void stepAt(double dt);
    void renderNextFrame();
    pybind11::array readBack(const std::string& target, bool check, const std::string& dtype);
    void makeCurrent();

    std::shared_ptr<PyWorkspace> ws_;
    glm::ivec2 size_{0};
    bool timing_ = false;
    std::unique_ptr<GlContext> context_;
    std::unique_ptr<GlExecutor> executor_;
    std::optional<Plan> plan_;
    std::uint64_t valuesRevision_ = 0;
    std::map<std::string, std::string> inputFiles_;  // for explain(): what each input was given
    double frameBudget_ = 0.0;
    std::size_t memoryBudget_ = kDefaultMemoryBudget;
    bool contentSkip_ = true;
    bool poolTargets_ = true;
    std::optional<FrameStepper> steps_;  // none: no frame since the run was built
    long stepsBase_ = 0;                 // the frame steps_ counts its indices from
    long nextFrame_ = 0;                 // the index (in the run's timeline) of the next frame
    std::vector<PassTiming> timings_;
    double frameMilliseconds_ = 0.0;
    std::vector<HealthFinding> findings_;
    Diagnostics warnings_;
};

// rmfx.Renderer, rmfx.PassTiming, rmfx.HealthFinding, and Workspace.renderer(…).
void bindRenderer(pybind11::module_& m);

}  // namespace rmfx::python
