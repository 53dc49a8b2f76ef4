// develop()'s keyword arguments as the library's DisplaySettings, shared by develop() and
// write_image(): exposure, tonemap, reinhard_white, display, gamut, bits, dither.
#pragma once
#include <pybind11/pybind11.h>

#include "obscura/color/display.h"

namespace obscura::python {

namespace py = pybind11;

// Raises TypeError for an unknown keyword and ValueError for an unknown name or a value out of
// range, naming the keyword and what was expected.
DisplaySettings display_settings_from(const py::kwargs& kwargs);

}  // namespace obscura::python
