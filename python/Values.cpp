#include "python/Values.h"

#include "python/Errors.h"

namespace py = pybind11;

namespace rmfx::python {

py::object toPython(const Value& value) {
    switch (value.type) {
        case ValueType::Float: return py::float_(value.asFloat());
        case ValueType::Int: return py::int_(value.asInt());
        case ValueType::Bool: return py::bool_(value.asBool());
        default: break;
    }
    const int n = componentCount(value.type);
    py::tuple t(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) t[static_cast<size_t>(i)] = py::float_(value.data[static_cast<size_t>(i)]);
    return t;
}

namespace {

std::string numberText(const std::string& name, const py::handle& value) {
    if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
    if (py::isinstance<py::int_>(value)) return py::str(value).cast<std::string>();
    if (py::isinstance<py::float_>(value)) return py::repr(value).cast<std::string>();
    // NumPy scalars and anything else that is a number.
    if (py::hasattr(value, "__float__") && !py::isinstance<py::str>(value))
        return py::repr(py::float_(py::reinterpret_borrow<py::object>(value))).cast<std::string>();
    fail("variable '" + name + "': cannot take a value of type " +
             py::str(value.get_type().attr("__name__")).cast<std::string>() +
             " (a number, True/False, a sequence of numbers, or the text --set takes)",
         "variable " + name);
}

}  // namespace

std::string valueText(const std::string& name, const py::handle& value) {
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    if (py::isinstance<py::bool_>(value) || py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value))
        return numberText(name, value);
    // A NumPy scalar or 0-d array is a number, though a 0-d array has __len__ too.
    if (py::hasattr(value, "ndim") && py::int_(value.attr("ndim")).cast<int>() == 0) return numberText(name, value);
    if (py::hasattr(value, "__len__") && py::hasattr(value, "__iter__") && !py::isinstance<py::bytes>(value)) {
        std::string text;
        for (py::handle item : value) {
            if (py::isinstance<py::str>(item) || (py::hasattr(item, "__len__") && py::hasattr(item, "__iter__")))
                fail("variable '" + name + "': a sequence of numbers, got an element that is not a number",
                     "variable " + name);
            text += (text.empty() ? "" : " ") + numberText(name, item);
        }
        return text;
    }
    return numberText(name, value);
}

}  // namespace rmfx::python
