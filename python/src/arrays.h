// Between numpy arrays and Obscura's buffers: handing an Image to Python without copying it, and
// checking arrays that come from Python (dtype, shape, layout, finite values) with messages that
// say which argument was wrong and what was expected.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "obscura/film/image.h"
#include "obscura/math/matrix4.h"

namespace obscura::python {

namespace py = pybind11;

// The image as a float32 array of shape (height, width, channels) that shares its memory: the
// Image is moved into a capsule, which becomes the array's base and frees it with the array.
py::array_t<float> image_to_array(Image&& image);

// Any owned vector as a 1-D/N-D array without a copy (the vector moves into the array's base).
template <typename T>
py::array_t<T> vector_to_array(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule base(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(shape, owned->data(), base);
}

// A float32 or float64, C-contiguous array of shape (..., last_dim) (last_dim 0: any), with
// finite values when `finite` is set. Raises TypeError for another type or dtype and ValueError
// for another shape, a strided view or a NaN/Inf, naming `what`. Python lists and tuples are
// taken as float64 arrays.
py::array checked_float_array(const py::handle& value, const char* what, py::ssize_t last_dim,
                              bool finite = true);

// checked_float_array, then exactly two dimensions: (N, last_dim).
py::array checked_points(const py::handle& value, const char* what, py::ssize_t last_dim,
                         bool finite = true);

// The values of a float32/float64 array as doubles (a copy for float32).
std::vector<double> as_doubles(const py::array& array);

// A (height, width, channels) or (height, width) float array as an Image (a copy).
Image array_to_image(const py::handle& value, const char* what);

// A 4x4 matrix as a float64 (4, 4) array, and back (ValueError naming `what` for another shape).
py::array_t<double> matrix_to_array(const Matrix4& m);
Matrix4 array_to_matrix(const py::handle& value, const char* what);

}  // namespace obscura::python
