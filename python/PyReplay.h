#pragma once
// rmfx.replay(manifest, …): rmfx replay's cases run in the calling process, each result an object
// (the case, its compares with their measured errors and the images) for pytest and pipelines to
// assert on; rmfx.replay_cases(manifest) lists the cases without rendering (for parametrize).

#include <pybind11/pybind11.h>

namespace rmfx::python {

// rmfx.replay, rmfx.replay_cases, rmfx.ReplayReport, rmfx.ReplayCase, rmfx.ReplayCompare.
void bindReplay(pybind11::module_& m);

}  // namespace rmfx::python
