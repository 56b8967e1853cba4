#pragma once
// Variable values between Python and the runtime: a float, an int, a bool, or a tuple of floats
// (vectors, colours, column-major matrices) out; the same, or the text `--set` takes, in.

#include <string>

#include <pybind11/pybind11.h>

#include "core/Value.h"

namespace rmfx::python {

pybind11::object toPython(const Value& value);
// The text form applyOverrides parses (the same as `rmfx render --set NAME=TEXT`): a str as it is,
// True/False as true/false, numbers in their shortest form, a sequence of numbers spaced. A value
// of another kind raises rmfx.Error naming `name`.
std::string valueText(const std::string& name, const pybind11::handle& value);

}  // namespace rmfx::python
