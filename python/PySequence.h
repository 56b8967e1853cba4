#pragma once
// Renderer.sequence(frames, …): a shot as a Python iterator, one array out per image in, as rmfx
// render runs a sequence: frame k of the shot at time k·dt, frame="previous" targets and light
// adaptation carried from frame to frame. Its start, pre-roll and skip place a chunk in the whole
// shot's run (io/media/SequenceChunk.h; rmfx.sequence_chunk), which rmfx.dask splits a shot with.

#include <optional>
#include <string>

#include <pybind11/pybind11.h>

namespace rmfx::python {

struct SequenceOptions {
    std::optional<std::string> input;  // the <input> the frames fill; none: the workspace's only one
    pybind11::dict inputs;             // images for the other inputs, the same for every frame
    double dt = 1.0 / 24.0;
    int start = 0;    // the shot index of the first item: its time is start·dt
    int preroll = 0;  // frames of the first item before it
    int skip = 0;     // items rendered as warm-up, not yielded
    std::string target;
    std::string dtype = "float32";  // or "target" (Renderer.render's dtype)
};

class PySequence {
public:
    PySequence(pybind11::object renderer, pybind11::iterable frames, SequenceOptions options);
    pybind11::object next();  // raises StopIteration after the last item

private:
    pybind11::dict inputsOf(const pybind11::handle& item) const;

    pybind11::object renderer_;  // an rmfx.Renderer, kept alive while the iterator lives
    pybind11::iterator frames_;
    SequenceOptions options_;
    std::string input_;
    bool started_ = false;
    long items_ = 0;  // taken from frames_
};

// Renderer.sequence, rmfx.sequence_chunk, rmfx.SequenceChunk.
void bindSequence(pybind11::module_& m);

}  // namespace rmfx::python
