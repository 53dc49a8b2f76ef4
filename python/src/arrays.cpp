#include "arrays.h"

#include <cmath>
#include <cstring>

namespace obscura::python {

py::array_t<float> image_to_array(Image&& image) {
  auto* owned = new Image(std::move(image));
  py::capsule base(owned, [](void* p) { delete static_cast<Image*>(p); });
  const py::ssize_t h = owned->height, w = owned->width, c = owned->channels;
  const py::ssize_t item = sizeof(float);
  return py::array_t<float>({h, w, c}, {w * c * item, c * item, item}, owned->data.data(), base);
}

namespace {

std::string shape_text(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) text += (i ? ", " : "") + std::to_string(a.shape(i));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

template <typename T>
bool all_finite(const py::array& a) {
  const T* p = static_cast<const T*>(a.data());
  for (py::ssize_t i = 0, n = a.size(); i < n; ++i)
    if (!std::isfinite(p[i])) return false;
  return true;
}

}  // namespace

py::array checked_float_array(const py::handle& value, const char* what, py::ssize_t last_dim,
                              bool finite) {
  py::array array;
  if (py::isinstance<py::array>(value)) {
    array = py::reinterpret_borrow<py::array>(value);
  } else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    try {
      array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
    } catch (const py::error_already_set&) {
    }
    if (!array) throw py::type_error(std::string(what) + ": expected a list of numbers");
  } else {
    throw py::type_error(std::string(what) +
                         ": expected a numpy array of float32 or float64, got " +
                         std::string(py::str(py::type::of(value).attr("__name__"))));
  }
  const bool is_f32 = array.dtype().is(py::dtype::of<float>());
  const bool is_f64 = array.dtype().is(py::dtype::of<double>());
  if (!is_f32 && !is_f64)
    throw py::type_error(std::string(what) + ": expected dtype float32 or float64, got " +
                         std::string(py::str(array.dtype())));
  if (array.ndim() < 1 || (last_dim > 0 && array.shape(array.ndim() - 1) != last_dim))
    throw py::value_error(std::string(what) + ": expected shape (..., " + std::to_string(last_dim) +
                          "), got " + shape_text(array));
  if (!(array.flags() & py::array::c_style))
    throw py::value_error(std::string(what) +
                          ": expected a C-contiguous array, got a strided view "
                          "(pass numpy.ascontiguousarray(...))");
  if (finite && !(is_f32 ? all_finite<float>(array) : all_finite<double>(array)))
    throw py::value_error(std::string(what) + ": expected finite values, found NaN or Inf");
  return array;
}

py::array checked_points(const py::handle& value, const char* what, py::ssize_t last_dim,
                         bool finite) {
  py::array array = checked_float_array(value, what, last_dim, finite);
  if (array.ndim() != 2)
    throw py::value_error(std::string(what) + ": expected shape (N, " + std::to_string(last_dim) +
                          "), got " + shape_text(array));
  return array;
}

std::vector<double> as_doubles(const py::array& array) {
  std::vector<double> values(size_t(array.size()));
  if (array.dtype().is(py::dtype::of<double>())) {
    std::memcpy(values.data(), array.data(), values.size() * sizeof(double));
  } else {
    const float* p = static_cast<const float*>(array.data());
    for (size_t i = 0; i < values.size(); ++i) values[i] = p[i];
  }
  return values;
}

Image array_to_image(const py::handle& value, const char* what) {
  py::array array = checked_float_array(value, what, 0, false);
  if (array.ndim() != 2 && array.ndim() != 3)
    throw py::value_error(std::string(what) + ": expected shape (height, width[, channels]), got " +
                          shape_text(array));
  const int channels = array.ndim() == 3 ? int(array.shape(2)) : 1;
  if (array.shape(0) < 1 || array.shape(1) < 1 || channels < 1 || channels > 4)
    throw py::value_error(std::string(what) +
                          ": expected a non-empty image of 1 to 4 channels, got shape " +
                          shape_text(array));
  Image image(int(array.shape(1)), int(array.shape(0)), channels);
  if (array.dtype().is(py::dtype::of<float>())) {
    std::memcpy(image.data.data(), array.data(), image.data.size() * sizeof(float));
  } else {
    const double* p = static_cast<const double*>(array.data());
    for (size_t i = 0; i < image.data.size(); ++i) image.data[i] = float(p[i]);
  }
  return image;
}

py::array_t<double> matrix_to_array(const Matrix4& m) {
  py::array_t<double> out({4, 4});
  auto a = out.mutable_unchecked<2>();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) a(i, j) = m[i][j];
  return out;
}

Matrix4 array_to_matrix(const py::handle& value, const char* what) {
  py::array a = checked_float_array(value, what, 4);
  if (a.ndim() != 2 || a.shape(0) != 4)
    throw py::value_error(std::string(what) + ": expected a 4x4 matrix");
  std::vector<double> v = as_doubles(a);
  Matrix4 m;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m[i][j] = v[size_t(4 * i + j)];
  return m;
}

}  // namespace obscura::python
