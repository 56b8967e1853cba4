#include "python/Errors.h"

#include <utility>

#include <pybind11/stl.h>

namespace py = pybind11;

namespace rmfx::python {

namespace {

// rmfx.Error, created once when the module is imported (owned by the module from then on).
PyObject* errorType = nullptr;

const char* severityName(Diagnostic::Severity severity) {
    return severity == Diagnostic::Severity::Error ? "error" : "warning";
}

std::string messageOf(const Diagnostics& diagnostics) {
    std::string message;
    for (const Diagnostic& d : diagnostics) {
        if (d.severity != Diagnostic::Severity::Error) continue;
        if (!message.empty()) message += '\n';
        // One without a file (a wrong argument) is its message alone: it names what it is about.
        message += d.where.file.empty() ? d.message : d.format();
    }
    return message;
}

// An instance of rmfx.Error with the first error's location as its attributes.
void raise(const Diagnostics& diagnostics) {
    const Diagnostic* first = nullptr;
    for (const Diagnostic& d : diagnostics)
        if (d.severity == Diagnostic::Severity::Error && !first) first = &d;
    py::object type = py::reinterpret_borrow<py::object>(errorType);
    py::object error = type(messageOf(diagnostics));
    error.attr("file") = first && !first->where.file.empty() ? py::object(py::str(first->where.file)) : py::object(py::none());
    error.attr("line") = first && first->where.line > 0 ? py::object(py::int_(first->where.line)) : py::object(py::none());
    error.attr("element") = first && !first->element.empty() ? py::object(py::str(first->element)) : py::object(py::none());
    error.attr("diagnostics") = py::cast(diagnostics);
    PyErr_SetObject(errorType, error.ptr());
}

}  // namespace

void fail(Diagnostics diagnostics) {
    if (!hasErrors(diagnostics)) diagnostics.push_back({Diagnostic::Severity::Error, {}, "", "failed"});
    throw Failure{std::move(diagnostics)};
}

void fail(const std::string& message, const std::string& element) {
    throw Failure{{{Diagnostic::Severity::Error, {}, element, message}}};
}

void bindErrors(py::module_& m) {
    py::class_<Diagnostic>(m, "Diagnostic", "A problem the runtime found: an error or a warning, with where it is.")
        .def_property_readonly("severity", [](const Diagnostic& d) { return severityName(d.severity); },
                               "'error' or 'warning'")
        .def_property_readonly("file", [](const Diagnostic& d) -> py::object {
            return d.where.file.empty() ? py::object(py::none()) : py::object(py::str(d.where.file));
        })
        .def_property_readonly("line", [](const Diagnostic& d) -> py::object {
            return d.where.line > 0 ? py::object(py::int_(d.where.line)) : py::object(py::none());
        }, "1-based; None where the problem has no line")
        .def_property_readonly("element", [](const Diagnostic& d) -> py::object {
            return d.element.empty() ? py::object(py::none()) : py::object(py::str(d.element));
        }, "the element, variable or argument it is about, where it names one")
        .def_readonly("message", &Diagnostic::message)
        .def("__str__", &Diagnostic::format)
        .def("__repr__", [](const Diagnostic& d) { return "<rmfx.Diagnostic " + d.format() + ">"; })
        // Picklable, so that an rmfx.Error raised in another process (a Dask worker) arrives whole.
        .def(py::pickle(
            [](const Diagnostic& d) {
                return py::make_tuple(severityName(d.severity), d.where.file, d.where.line, d.element, d.message);
            },
            [](const py::tuple& t) {
                if (t.size() != 5) fail("a pickled rmfx.Diagnostic of another version", "pickle");
                Diagnostic d;
                d.severity = t[0].cast<std::string>() == "error" ? Diagnostic::Severity::Error : Diagnostic::Severity::Warning;
                d.where = {t[1].cast<std::string>(), t[2].cast<int>()};
                d.element = t[3].cast<std::string>();
                d.message = t[4].cast<std::string>();
                return d;
            }));

    errorType = PyErr_NewExceptionWithDoc(
        "rmfx.Error",
        "A problem with a workspace, a value or an input. Attributes: file, line and element of the first error (None "
        "where it has none) and diagnostics, every rmfx.Diagnostic that came with it.",
        PyExc_Exception, nullptr);
    if (!errorType) throw py::error_already_set();
    m.add_object("Error", py::reinterpret_borrow<py::object>(errorType));

    // For the module's Python files (rmfx.dask): an rmfx.Error as the compiled code raises it.
    m.def("_fail", [](const std::string& message, const std::string& element) { fail(message, element); }, py::arg("message"),
          py::arg("element") = "");

    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const Failure& failure) {
            raise(failure.diagnostics);
        }
    });
}

}  // namespace rmfx::python
