#include "python/PySequence.h"

#include <utility>

#include <pybind11/stl.h>

#include "python/Errors.h"
#include "python/PyRenderer.h"
#include "io/media/SequenceChunk.h"

namespace py = pybind11;

namespace rmfx::python {

PySequence::PySequence(py::object renderer, py::iterable frames, SequenceOptions options)
    : renderer_(std::move(renderer)), frames_(py::iter(frames)), options_(std::move(options)) {
    PyRenderer& r = renderer_.cast<PyRenderer&>();
    const Workspace& ws = r.workspace().ws();
    if (options_.input) {
        input_ = *options_.input;
        if (!ws.findInput(input_)) fail("input: the workspace has no input '" + input_ + "'", "input " + input_);
    } else if (ws.inputs.size() == 1) {
        input_ = ws.inputs.front().name;
    } else {
        fail(std::string("input: name the <input> the frames fill; the workspace declares ") +
                 (ws.inputs.empty() ? "none" : std::to_string(ws.inputs.size())),
             "input");
    }
    if (options_.inputs.contains(input_))
        fail("inputs: '" + input_ + "' is the input the frames fill; give its images as the frames", "input " + input_);
    if (options_.skip < 0) fail("skip: expected 0 or more frames, got " + std::to_string(options_.skip), "skip");
}

py::dict PySequence::inputsOf(const py::handle& item) const {
    py::dict given;
    for (auto [name, image] : options_.inputs) given[name] = image;
    given[py::str(input_)] = item;
    return given;
}

py::object PySequence::next() {
    PyRenderer& r = renderer_.cast<PyRenderer&>();
    for (;;) {
        if (frames_ == py::iterator::sentinel()) throw py::stop_iteration();
        py::object item = py::reinterpret_borrow<py::object>(*frames_);
        ++frames_;
        const py::dict given = inputsOf(item);
        if (!started_) {
            r.beginSequence(given, options_.target, options_.dt, options_.start, options_.preroll);
            started_ = true;
        }
        const bool warmUp = items_ < options_.skip;
        ++items_;
        py::object image = r.stepSequence(given, !warmUp, options_.dtype);
        if (!warmUp) return image;
    }
}

void bindSequence(py::module_& m) {
    py::class_<PySequence>(m, "Sequence", "The iterator Renderer.sequence returns: one array per frame.")
        .def("__iter__", [](PySequence& s) -> PySequence& { return s; })
        .def("__next__", &PySequence::next);

    py::class_<SequenceChunk>(m, "SequenceChunk",
        "Where a chunk of a shot starts in the whole run (rmfx.sequence_chunk): Renderer.sequence(frames[start:last + 1], "
        "start=start, preroll=preroll, skip=skip) yields the chunk's frames as the whole run gives them.")
        .def_readonly("start", &SequenceChunk::start, "the first frame the chunk reads (0-based in the shot)")
        .def_readonly("preroll", &SequenceChunk::preroll, "frames of that image before it, at the times before start")
        .def_readonly("skip", &SequenceChunk::skip, "frames start … start + skip - 1 rendered as warm-up, not yielded")
        .def("__repr__", [](const SequenceChunk& c) {
            return "<rmfx.SequenceChunk start=" + std::to_string(c.start) + " preroll=" + std::to_string(c.preroll) +
                   " skip=" + std::to_string(c.skip) + ">";
        });
    m.def("sequence_chunk", [](int first, int preroll) {
        if (first < 0) fail("first: expected a frame index from 0, got " + std::to_string(first), "first");
        if (preroll < 0) fail("preroll: expected 0 or more frames, got " + std::to_string(preroll), "preroll");
        return planSequenceChunk(first, preroll);
    }, py::arg("first"), py::arg("preroll"),
    "sequence_chunk(first, preroll) -> SequenceChunk: the warm-up of a chunk whose first written frame is `first` "
    "(0-based in the shot) when the whole run renders `preroll` frames of its first image before frame 0: the last "
    "`preroll` frames of that run before `first`, as rmfx render --frame-range renders them.");

    py::reinterpret_borrow<py::class_<PyRenderer>>(m.attr("Renderer"))
        .def("sequence", [](py::object self, py::iterable frames, std::optional<std::string> input, std::optional<py::dict> inputs,
                            std::optional<double> dt, std::optional<double> fps, int preroll, int start, int skip, const std::string& target,
                            const std::string& dtype) {
            if (dtype != "float32" && dtype != "target")
                fail("dtype: expected 'float32' or 'target' (the target's own type), got '" + dtype + "'", "dtype");
            if (dt && fps) fail("dt and fps both set a sequence's time step (dt = 1 / fps): give one", "fps");
            if (fps && (!(*fps > 0.0) || *fps > 10000.0))
                fail("fps: expected frames per second above 0, got " + std::to_string(*fps), "fps");
            SequenceOptions o;
            o.input = std::move(input);
            if (inputs) o.inputs = *inputs;
            o.dt = dt.value_or(1.0 / fps.value_or(24.0));
            o.preroll = preroll;
            o.start = start;
            o.skip = skip;
            o.target = target;
            o.dtype = dtype;
            return PySequence(std::move(self), std::move(frames), std::move(o));
        }, py::arg("frames"), py::kw_only(), py::arg("input") = py::none(), py::arg("inputs") = py::none(),
        py::arg("dt") = py::none(), py::arg("fps") = py::none(), py::arg("preroll") = 0, py::arg("start") = 0, py::arg("skip") = 0,
        py::arg("target") = "", py::arg("dtype") = "float32",
        "sequence(frames, *, input=None, inputs=None, dt=None, fps=None, preroll=0, start=0, skip=0, target='', "
        "dtype='float32') -> iterator\n\n"
        "Renders a shot as rmfx render --input shot.%04d.exr does, one float32 (height, width, 4) array per item of "
        "`frames` (arrays or paths, as render's inputs take them), lazily: frame k at time k·dt (dt = 1 / fps, fps 24 unless given), "
        "frame=\"previous\" targets and light adaptation carried from frame to frame. The run starts anew from the "
        "workspace's initial state when the first item is taken. input: the <input> the frames fill (default: the "
        "workspace's only one); inputs: images for the other inputs, the same for every frame. preroll: frames of the "
        "first item before it (rmfx render --preroll). start: the shot index of the first item (its time is "
        "start·dt); skip: that many first items are rendered as warm-up and not yielded: rmfx.sequence_chunk gives "
        "the three for a chunk of a shot.");
}

}  // namespace rmfx::python
