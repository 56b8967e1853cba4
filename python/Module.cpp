// import rmfx: the runtime as a Python module (docs/python.md). One concept a file: Errors
// (rmfx.Error, rmfx.Diagnostic), Values, Arrays, PyWorkspace (rmfx.load), PyRenderer,
// PySequence, PyReplay.

#include <pybind11/pybind11.h>

#include "python/Errors.h"
#include "python/PyRenderer.h"
#include "python/PyReplay.h"
#include "python/PySequence.h"
#include "python/PyWorkspace.h"

namespace py = pybind11;

PYBIND11_MODULE(_rmfx, m) {
    m.doc() = "rmfx effect workspaces, rendered headless into NumPy arrays (row 0 at the top). See docs/python.md.";
    m.attr("__version__") = RMFX_VERSION;
    rmfx::python::bindErrors(m);
    rmfx::python::bindWorkspace(m);
    rmfx::python::bindRenderer(m);
    rmfx::python::bindSequence(m);
    rmfx::python::bindReplay(m);
}
