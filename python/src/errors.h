// Obscura's errors as Python exceptions.
#pragma once
#include <pybind11/pybind11.h>

namespace obscura::python {

namespace py = pybind11;

// obscura.RenderInterrupted (a KeyboardInterrupt): raised by render() on Ctrl-C, carrying the
// image rendered so far. Valid after bind_errors.
py::handle render_interrupted_type();

}  // namespace obscura::python
