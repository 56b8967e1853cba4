#include "python/PyRenderer.h"

#include <algorithm>
#include <chrono>
#include <utility>

#include <pybind11/stl.h>

#include "compile/CompiledFrame.h"
#include "graph/FrameExplanation.h"
#include "io/image/InputImage.h"
#include "model/EffectSelection.h"
#include "python/Arrays.h"
#include "python/Errors.h"

namespace py = pybind11;

namespace rmfx::python {

namespace {

void checkDtype(const std::string& dtype) {
    if (dtype != "float32" && dtype != "target")
        fail("dtype: expected 'float32' or 'target' (the target's own type), got '" + dtype + "'", "dtype");
}

void append(Diagnostics& to, Diagnostics from) { to.insert(to.end(), from.begin(), from.end()); }

bool isPath(const py::handle& value) {
    return py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__");
}

// The compiled frame of a request without GL: what explain() shows before any render.
FrameExplanationInput explanationWithoutFrame(const PreparedRun& run) {
    const CompiledFrame& frame = *run.frame;
    return explanationOf(frame, switchedOffEffects(frame.ws(), frame.plan.askedEffects, frame.values));
}

}  // namespace

PyRenderer::PyRenderer(std::shared_ptr<PyWorkspace> ws, glm::ivec2 size, bool timing, double frameBudget)
    : ws_(std::move(ws)), size_(size), timing_(timing), frameBudget_(frameBudget) {
    if (!(frameBudget_ >= 0.0) || frameBudget_ > 86400.0)
        fail("frame_budget: expected seconds from 0 (no limit) to 86400, got " + std::to_string(frameBudget_), "frame_budget");
    if (!ws_) fail("workspace: expected an rmfx.Workspace (rmfx.load), got None", "workspace");
    if (size_.x < 0 || size_.y < 0 || (size_.x == 0) != (size_.y == 0) || size_.x > 16384 || size_.y > 16384)
        fail("size: expected (width, height) from 1 to 16384 each, got (" + std::to_string(size_.x) + ", " +
                 std::to_string(size_.y) + ")",
             "size");
}

void PyRenderer::setRunOptions(std::optional<double> memoryBudgetMiB, bool contentSkip, bool poolTargets) {
    if (memoryBudgetMiB) {
        if (!(*memoryBudgetMiB > 0.0) || *memoryBudgetMiB > 1048576.0)
            fail("memory_budget: expected MiB of render-target memory above 0 (up to 1048576), got " +
                     std::to_string(*memoryBudgetMiB),
                 "memory_budget");
        memoryBudget_ = static_cast<std::size_t>(*memoryBudgetMiB * 1048576.0);
    }
    contentSkip_ = contentSkip;
    poolTargets_ = poolTargets;
}

PyRenderer::~PyRenderer() {
    if (executor_) {
        makeCurrent();  // the executor deletes its GL objects in its context
        executor_.reset();
    }
}

void PyRenderer::makeCurrent() {
    if (context_) context_->makeCurrent();
}

std::vector<PyRenderer::Given> PyRenderer::readInputs(const py::dict& inputs) const {
    std::vector<Given> given;
    for (auto [key, value] : inputs) {
        if (!py::isinstance<py::str>(key)) fail("inputs: the keys are the names of the workspace's <input>s", "inputs");
        Given g;
        g.argument.name = key.cast<std::string>();
        g.input = ws_->ws().findInput(g.argument.name);
        if (!g.input) {
            std::string known;
            for (const ImageInput& i : ws_->ws().inputs) known += (known.empty() ? "'" : ", '") + i.name + "'";
            fail("the workspace has no input '" + g.argument.name + "' (" +
                     (known.empty() ? "it declares no <input>" : "its inputs: " + known) + ")",
                 "input " + g.argument.name);
        }
        if (isPath(value)) {
            const std::string text = py::str(py::module_::import("os").attr("fspath")(value)).cast<std::string>();
            auto [file, layer] = splitLayerSuffix(text);
            g.argument.file = file;
            g.argument.layer = layer;
            g.argument.text = g.argument.name + "=" + text;
            Result<InputImage> read = readInputImage(file, layer);
            if (!read) fail({{Diagnostic::Severity::Error, {ws_->ws().path.string(), 0}, "input " + g.argument.text, read.error()}});
            g.argument.image = std::make_shared<const Image>(std::move(read->image));
        } else {
            g.direct = directPixels(value);
            g.array = py::reinterpret_borrow<py::object>(value);
            if (!g.direct)
                g.argument.image = std::make_shared<const Image>(imageFromArray(value, "input '" + g.argument.name + "'"));
            g.argument.file = "array";
        }
        g.size = g.argument.image ? glm::ivec2(g.argument.image->width, g.argument.image->height)
                                  : glm::ivec2(g.direct->width, g.direct->height);
        if (g.argument.file == "array")
            g.argument.text = g.argument.name + "=<array " + std::to_string(g.size.x) + "x" + std::to_string(g.size.y) + ">";
        given.push_back(std::move(g));
    }
    return given;
}

const std::shared_ptr<const Image>& PyRenderer::imageOf(Given& g) {
    if (!g.argument.image)
        g.argument.image = std::make_shared<const Image>(imageFromArray(g.array, "input '" + g.argument.name + "'"));
    return g.argument.image;
}

// The run compiled anew, as rmfx render compiles it: the loaded workspace with its values, the
// inputs read into it (readRunInputs), the frame compiled (compileRun), the executor created.
void PyRenderer::build(std::vector<Given>& given, const Plan& plan) {
    RunRequest request = ws_->request();
    for (Given& g : given) {
        imageOf(g);
        request.inputs.push_back(g.argument);
    }
    request.size = size_;
    request.plan.outputs = {plan.target};
    request.plan.checkHealth = plan.check;
    request.plan.effects = ws_->effects();
    request.plan.memoryBudget = memoryBudget_;
    request.plan.contentSkip = contentSkip_;
    request.plan.poolTargets = poolTargets_;
    LoadedRun loaded = ws_->loaded();
    Diagnostics warnings;
    if (Result<void> read = readRunInputs(loaded, request); !read) fail(read.takeDiagnostics());
    else append(warnings, read.takeDiagnostics());
    Result<PreparedRun> prepared = compileRun(std::move(loaded), request);
    if (!prepared) fail(prepared.takeDiagnostics());
    append(warnings, prepared.takeDiagnostics());

    if (executor_) {
        makeCurrent();
        executor_.reset();
        plan_.reset();
    }
    if (!context_) {
        Result<std::unique_ptr<GlContext>> context = GlContext::createHeadless(prepared->ws().profile);
        if (!context) fail(context.error());
        context_ = std::move(*context);
    }
    makeCurrent();
    Result<std::unique_ptr<GlExecutor>> created = GlExecutor::create(prepared->frame, GlRunSettings{});
    if (!created) fail(created.takeDiagnostics());
    append(warnings, created.takeDiagnostics());
    executor_ = std::move(*created);
    executor_->setTimingEnabled(timing_);
    plan_ = plan;
    valuesRevision_ = ws_->valuesRevision();
    steps_.reset();
    stepsBase_ = nextFrame_ = 0;
    inputFiles_.clear();
    for (const Given& g : given) inputFiles_[g.argument.name] = g.argument.text.substr(g.argument.name.size() + 1);
    warnings_ = std::move(warnings);
}

// The kept executor given the workspace's current values and this call's images.
void PyRenderer::update(std::vector<Given>& given) {
    makeCurrent();
    warnings_.clear();
    if (valuesRevision_ != ws_->valuesRevision()) {
        for (const Variable& v : ws_->ws().variables) {
            if (!v.semantic.empty()) continue;
            const Value* current = executor_->variable(v.name);
            if (!current || *current == v.value) continue;  // none: no pass of the run reads it
            if (Result<void> set = executor_->setVariable(v.name, v.value); !set) fail(set.takeDiagnostics());
        }
        valuesRevision_ = ws_->valuesRevision();
    }
    const glm::ivec2 viewport = executor_->viewport();
    for (Given& g : given) {
        inputFiles_[g.argument.name] = g.argument.text.substr(g.argument.name.size() + 1);
        const bool toResample = g.input->sizesViewport && g.size != viewport;
        if (g.direct && !toResample && executor_->writeInputPixels(g.argument.name, *g.direct)) continue;
        std::shared_ptr<const Image> image = imageOf(g);
        if (toResample) {
            // As readRunInputs resampled the image the run was built with (a size was given).
            Result<Image> resampled = resampleImage(*image, viewport.x, viewport.y);
            if (!resampled) fail("input '" + g.argument.name + "': " + resampled.error(), "input " + g.argument.name);
            image = std::make_shared<const Image>(std::move(*resampled));
        }
        if (Result<void> replaced = executor_->replaceInputImage(g.argument.name, image); !replaced)
            fail(replaced.takeDiagnostics());
    }
}

PyRenderer::Plan PyRenderer::planFor(const std::vector<Given>& given, const std::string& target, bool check) const {
    Plan plan;
    plan.target = target.empty() ? ws_->ws().outputTargetName() : target;
    if (!ws_->ws().canReadTarget(plan.target))
        fail("target " + plan.target + ": the workspace has no such target (" + ws_->ws().describeTargets() + ")", "target");
    plan.check = check;
    plan.effectsRevision = ws_->effectsRevision();
    for (const Given& g : given) plan.inputs.emplace_back(g.argument.name, g.size);
    std::sort(plan.inputs.begin(), plan.inputs.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    return plan;
}

void PyRenderer::stepAt(double dt) {
    const float step = static_cast<float>(dt);
    if (steps_ && steps_->dt() == step) return;
    // Frame i of a run at time i·dt, as run/FrameStepper steps rmfx render's frames; after a
    // change of dt, time goes on from the next frame's.
    const float origin = steps_ ? steps_->time(nextFrame_ - stepsBase_) : 0.0f;
    stepsBase_ = steps_ ? nextFrame_ : 0;
    steps_.emplace(step, frameBudget_, std::function<void(const std::string&)>{}, origin);
}

void PyRenderer::renderNextFrame() {
    const std::string label = "frame " + std::to_string(executor_->frameIndex() + 1) + " of " + ws_->ws().path.string();
    Result<void> frame = steps_->step(*executor_, nextFrame_ - stepsBase_, label);
    Diagnostics d = frame.takeDiagnostics();
    if (hasErrors(d)) fail(std::move(d));
    append(warnings_, std::move(d));
    ++nextFrame_;
}

py::array PyRenderer::readBack(const std::string& target, bool check, const std::string& dtype) {
    Result<Image> image = [&] {
        py::gil_scoped_release unlocked;  // waits for the frame's GPU work
        return executor_->readTarget(target);
    }();
    if (!image) fail("target " + target + ": " + image.error(), "target");
    // The read back waited for the last frame, so its timer queries have all arrived.
    timings_ = timing_ ? executor_->passTimings() : std::vector<PassTiming>{};
    frameMilliseconds_ = timing_ ? executor_->frameGpuMilliseconds() : 0.0;
    findings_ = check ? executor_->firstHealthFindings() : std::vector<HealthFinding>{};
    if (dtype == "target") return targetArray(*image, executor_->targetFormat(target));
    return arrayFromImage(std::move(*image));
}

py::array PyRenderer::render(const py::dict& inputs, int frames, double dt, const std::string& target, bool check,
                             const std::string& dtype) {
    checkDtype(dtype);
    if (frames < 1 || frames > 100000) fail("frames: expected 1 to 100000, got " + std::to_string(frames), "frames");
    if (!(dt >= 0.0) || dt > 3600.0) fail("dt: expected seconds from 0 to 3600, got " + std::to_string(dt), "dt");
    std::vector<Given> given = readInputs(inputs);
    const Plan plan = planFor(given, target, check);
    if (executor_ && plan_ && *plan_ == plan) update(given);
    else build(given, plan);
    stepAt(dt);
    {
        py::gil_scoped_release unlocked;  // other Python threads run while the frames render
        for (int i = 0; i < frames; ++i) renderNextFrame();
    }
    return readBack(plan.target, check, dtype);
}

std::vector<double> PyRenderer::cppFrameLoop(const py::dict& inputs, int frames) {
    if (!executor_ || !plan_) fail("render once first: the loop times the run that render built", "renderer");
    if (frames < 1 || frames > 100000) fail("frames: expected 1 to 100000, got " + std::to_string(frames), "frames");
    std::vector<Given> given = readInputs(inputs);
    for (Given& g : given) imageOf(g);
    makeCurrent();
    std::vector<double> seconds;
    for (int i = 0; i < frames; ++i) {
        const auto start = std::chrono::steady_clock::now();
        for (const Given& g : given) {
            // The fastest way C++ has: the pixels written in place where the texture takes them.
            const Image& image = *g.argument.image;
            GlExecutor::InputPixels pixels{image.pixels.data(), image.width, image.height, false,
                                           std::size_t(image.width) * 4 * sizeof(float)};
            if (image.channels == 4 && executor_->writeInputPixels(g.argument.name, pixels)) continue;
            if (Result<void> replaced = executor_->replaceInputImage(g.argument.name, g.argument.image); !replaced)
                fail(replaced.takeDiagnostics());
        }
        renderNextFrame();
        Result<Image> image = executor_->readTarget(plan_->target);
        if (!image) fail("target " + plan_->target + ": " + image.error(), "target");
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return seconds;
}

void PyRenderer::beginSequence(const py::dict& inputs, const std::string& target, double dt, int first, int preroll) {
    if (!(dt >= 0.0) || dt > 3600.0) fail("dt: expected seconds from 0 to 3600, got " + std::to_string(dt), "dt");
    if (first < 0 || first > 10000000) fail("start: expected a frame index from 0, got " + std::to_string(first), "start");
    if (preroll < 0 || preroll > 100000) fail("preroll: expected 0 to 100000 frames, got " + std::to_string(preroll), "preroll");
    std::vector<Given> given = readInputs(inputs);
    build(given, planFor(given, target, false));  // a sequence starts from the workspace's initial state
    stepAt(dt);
    nextFrame_ = first - preroll;
    for (int p = 0; p < preroll; ++p) renderNextFrame();
}

py::object PyRenderer::stepSequence(const py::dict& inputs, bool read, const std::string& dtype) {
    if (!executor_ || !plan_) fail("the sequence's run was reset; start the sequence again", "sequence");
    std::vector<Given> given = readInputs(inputs);
    for (const Given& g : given)
        if (std::none_of(plan_->inputs.begin(), plan_->inputs.end(), [&](const auto& i) { return i.first == g.argument.name; }))
            fail("input '" + g.argument.name + "' was not given to the sequence's first frame", "input " + g.argument.name);
    update(given);
    {
        py::gil_scoped_release unlocked;
        renderNextFrame();
    }
    if (!read) return py::none();
    return readBack(plan_->target, false, dtype);
}

std::string PyRenderer::explain() {
    if (executor_) {
        makeCurrent();
        FrameExplanationInput explained = explanationOf(executor_->compiledFrame(), executor_->switchedOffEffects());
        explained.frameRan = executor_->frameIndex() > 0;
        explained.contentSkipped = executor_->contentSkippedEffects(true);
        explained.inputFiles = inputFiles_;
        return explainFrame(explained);
    }
    // No run yet: the plan of a render with no inputs given, compiled without GL (rmfx render --explain).
    RunRequest request = ws_->request();
    request.size = size_;
    request.plan.outputs = {ws_->ws().outputTargetName()};
    request.plan.effects = ws_->effects();
    Result<PreparedRun> prepared = compileRun(ws_->loaded(), request);
    if (!prepared) fail(prepared.takeDiagnostics());
    return explainFrame(explanationWithoutFrame(*prepared));
}

void PyRenderer::reset() {
    if (!executor_) return;
    makeCurrent();
    executor_.reset();
    plan_.reset();
    steps_.reset();
    stepsBase_ = nextFrame_ = 0;
}

std::vector<std::string> PyRenderer::passesRun() const {
    return executor_ ? executor_->passesRun() : std::vector<std::string>{};
}

namespace {

glm::ivec2 sizeOf(const std::optional<std::pair<int, int>>& size) {
    return size ? glm::ivec2(size->first, size->second) : glm::ivec2(0);
}

}  // namespace

void bindRenderer(py::module_& m) {
    py::class_<PassTiming>(m, "PassTiming", "GPU time of one pass of the last frame rendered.")
        .def_readonly("pass_", &PassTiming::pass)
        .def_property_readonly("name", [](const PassTiming& t) { return t.pass; })
        .def_readonly("milliseconds", &PassTiming::milliseconds)
        .def("__repr__", [](const PassTiming& t) { return "<rmfx.PassTiming " + t.pass + ": " + std::to_string(t.milliseconds) + " ms>"; });

    py::class_<HealthFinding>(m, "HealthFinding", "The first pixel of a kind (NaN, ±Inf, negative, at the format's largest) a pass left in its target.")
        .def_property_readonly("kind", [](const HealthFinding& f) { return std::string(healthKindName(f.kind)); })
        .def_property_readonly("is_error", [](const HealthFinding& f) { return healthKindIsError(f.kind); },
                               "NaN and infinities are errors; negatives and values at the format's largest warnings")
        .def_readonly("frame", &HealthFinding::frame, "counted from 0")
        .def_property_readonly("pass_", [](const HealthFinding& f) { return f.pass; })
        .def_readonly("target", &HealthFinding::target)
        .def_readonly("count", &HealthFinding::count, "pixels of that pass holding the kind")
        .def_property_readonly("pixel", [](const HealthFinding& f) { return py::make_tuple(f.pixel.x, f.pixel.y); })
        .def_property_readonly("value", [](const HealthFinding& f) -> py::object {
            if (!f.recorded) return py::none();
            return py::make_tuple(f.value.x, f.value.y, f.value.z, f.value.w);
        })
        .def("__str__", [](const HealthFinding& f) { return describeFinding(f); })
        .def("__repr__", [](const HealthFinding& f) { return "<rmfx.HealthFinding " + describeFinding(f) + ">"; });

    py::class_<PyRenderer>(m, "Renderer",
        "Renderer(workspace, size=None, timing=False, frame_budget=0, memory_budget=None, content_skip=True, "
        "pool_targets=True): renders a workspace headless, keeping its GL context and executor between calls (see "
        "render()). frame_budget: seconds a frame may take, GPU work included, as rmfx render --frame-budget: a frame "
        "past it ends the process with exit status 3 (a shader stuck in the driver cannot be interrupted otherwise); 0, "
        "the default: no limit. memory_budget: MiB of render-target memory a frame may hold (--memory-budget, default "
        "4096); content_skip=False runs effects whose source holds nothing all the same (--content-skip off); "
        "pool_targets=False gives every target memory of its own (--no-pool).")
        .def(py::init([](std::shared_ptr<PyWorkspace> ws, std::optional<std::pair<int, int>> size, bool timing, double budget,
                         std::optional<double> memory, bool contentSkip, bool pool) {
                 auto r = std::make_unique<PyRenderer>(std::move(ws), sizeOf(size), timing, budget);
                 r->setRunOptions(memory, contentSkip, pool);
                 return r;
             }),
             py::arg("workspace"), py::kw_only(), py::arg("size") = py::none(), py::arg("timing") = false,
             py::arg("frame_budget") = 0.0, py::arg("memory_budget") = py::none(), py::arg("content_skip") = true,
             py::arg("pool_targets") = true)
        .def("render", &PyRenderer::render, py::kw_only(), py::arg("inputs") = py::dict(), py::arg("frames") = 1,
             py::arg("dt") = double(1.0f / 60.0f), py::arg("target") = "", py::arg("check") = false, py::arg("dtype") = "float32",
             "render(*, inputs={}, frames=1, dt=1/60, target='', check=False, dtype='float32') -> numpy.ndarray\n\n"
             "Runs `frames` frames, dt seconds apart, and returns the target ('' the workspace's output) as a float32 "
             "array of shape (height, width, 4): linear RGBA, ROW 0 AT THE TOP of the image (as image files and NumPy's "
             "image libraries have it; OpenGL's own rows start at the bottom). The same pixels as `rmfx render --frames N "
             "--dt DT -o out.exr` with the same values and inputs.\n\n"
             "inputs: {name: image} for the workspace's <input>s; an image is a path (any file rmfx render --input reads, "
             "'file.exr:layer' too) or an array of shape (h, w, 3|4): float32 or float16 taken as linear, uint8 decoded "
             "from sRGB (alpha / 255); three channels get alpha 1.\n\n"
             "The executor is kept: a call with the same inputs given (at the same sizes), target, check and effects "
             "goes on from the last one's frames and time (state carried across calls: feedback targets, adaptation); "
             "new variable values and input images apply from this call. Anything else compiles the run anew and "
             "starts at time 0, as does reset(). check=True: inspect what each pass wrote (findings).\n\n"
             "dtype='target': the target's own type instead of float32: uint8 for 8-bit formats (rgba8, r8, rg8: the "
             "stored byte), uint16 for 16-bit integer ones (rgba16, rg16), float16 for half-float ones; float32 for the "
             "others (32-bit floats, r11g11b10f, rgb10a2, which NumPy has no type for). Single-channel targets have "
             "shape (height, width, 1).")
        .def("_cpp_frame_loop", &PyRenderer::cppFrameLoop, py::arg("inputs"), py::arg("frames"),
             "For bench/python-overhead.py: the seconds of each of `frames` frames of this renderer's run in a C++ loop "
             "(the inputs converted once before it), against which render()'s frames through Python are measured.")
        .def("explain", &PyRenderer::explain, "The plan: what rmfx render --explain prints (after a render, of that run).")
        .def("reset", &PyRenderer::reset, "Drops the executor: the next render compiles anew and starts at time 0.")
        .def_property_readonly("timings", &PyRenderer::timings, "per-pass GPU times of the last frame (Renderer(timing=True))")
        .def_property_readonly("frame_milliseconds", &PyRenderer::frameMilliseconds)
        .def_property_readonly("findings", &PyRenderer::findings, "with render(check=True): the first finding of each kind")
        .def_property_readonly("warnings", &PyRenderer::warnings, "the last render's warnings, as rmfx.Diagnostic")
        .def_property_readonly("frame", &PyRenderer::frame, "frames rendered since the run was compiled")
        .def_property_readonly("time", &PyRenderer::time, "the next frame's time in seconds")
        .def_property_readonly("size", [](const PyRenderer& r) { return py::make_tuple(r.viewport().x, r.viewport().y); })
        .def_property_readonly("passes_run", &PyRenderer::passesRun);

    // ws.renderer(size=…, timing=…): the same as rmfx.Renderer(ws, …).
    py::reinterpret_borrow<py::class_<PyWorkspace, std::shared_ptr<PyWorkspace>>>(m.attr("Workspace"))
        .def("renderer", [](std::shared_ptr<PyWorkspace> ws, std::optional<std::pair<int, int>> size, bool timing, double budget,
                            std::optional<double> memory, bool contentSkip, bool pool) {
            auto r = std::make_unique<PyRenderer>(std::move(ws), sizeOf(size), timing, budget);
            r->setRunOptions(memory, contentSkip, pool);
            return r;
        }, py::arg("size") = py::none(), py::kw_only(), py::arg("timing") = false, py::arg("frame_budget") = 0.0,
        py::arg("memory_budget") = py::none(), py::arg("content_skip") = true, py::arg("pool_targets") = true,
        "renderer(size=None, *, timing=False, frame_budget=0) -> Renderer: rmfx.Renderer(ws, size=size, …)");
}

}  // namespace rmfx::python
