#pragma once
// rmfx.Error: every problem the module reports, raised as a Python exception that carries the
// diagnostics (file, line, element, message) the runtime gave; and rmfx.Diagnostic, one of them.

#include <string>

#include <pybind11/pybind11.h>

#include "core/Diagnostic.h"

namespace rmfx::python {

// Thrown by the bindings; the module's exception translator raises it as rmfx.Error.
struct Failure {
    Diagnostics diagnostics;  // at least one error
};

// Raises rmfx.Error with these diagnostics (their errors make the message).
[[noreturn]] void fail(Diagnostics diagnostics);
// Raises rmfx.Error with one error without a location (a wrong array, an unknown name, …).
[[noreturn]] void fail(const std::string& message, const std::string& element = "");

// Defines rmfx.Error (a subclass of Exception) and rmfx.Diagnostic, and translates Failure.
void bindErrors(pybind11::module_& m);

}  // namespace rmfx::python
